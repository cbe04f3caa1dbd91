#pragma once

// `argus chaos`'s nemesis: for each seed, a random schedule of faults on a scenario, after
// Jepsen's nemeses (docs/chaos.md). Everything here is a function of the scenario and the
// seed, so that a seed's runs can be made again from its number alone.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "config/scenario.hpp"

namespace argus::apps {

/// What every seed's run shares.
struct chaos_settings {
  /// Each run's virtual length.
  config::seconds duration{180.0};
  /// No fault starts or lasts into the run's last stretch of this length: liveness is
  /// measured there.
  config::seconds quiet_tail{40.0};
  /// Every this-many-th seed senses as the scenario says (pixels for the shipped scenarios, with
  /// their tracker options); the others emulate sensing. 0: every seed emulates; 1: none does.
  std::uint64_t scenario_sensing_every = 10;
};

/// One seed's variant and faults.
struct chaos_plan {
  std::uint64_t seed = 1;
  config::merge_rule merge = config::merge_rule::highest_id;
  config::sensing_mode sensing = config::sensing_mode::emulated;
  double duplicate_probability = 0.0;
  bool reorder = false;
  std::vector<config::fault> faults;
  /// A task the operator cancels, and when.
  std::optional<std::pair<std::size_t, config::seconds>> cancel;
  /// Every fault is over (links healed, crashed cameras back, bursts and spikes ended) by then.
  config::seconds healed_at{0.0};
  /// What the seed does, one word per nemesis, for the report ("loss_burst", "partition", ...).
  std::vector<std::string> nemeses;
};

/// Seed `seed`'s plan for `scenario` (whose cameras, links and tasks it draws from).
/// Nemeses, each drawn independently: 0-2 loss bursts (2-10 s, loss 0.5-1), 0-2 delay spikes
/// (2-10 s, +0.5-3 s), a partition (a random split of the cameras, every link across cut, healed
/// 5-20 s later) with probability 0.6, 0-2 crashes with recovery (5-30 s), duplicates (2-10 %)
/// with probability 0.5, reordering with probability 0.5, and a cancelled task with probability
/// 0.25. Merge rule: highest_id for odd seeds, negotiation for even ones.
chaos_plan plan_chaos(const config::scenario& scenario, std::uint64_t seed,
                      const chaos_settings& settings);

/// `scenario` as seed `plan.seed` runs it: its duration, seed, merge rule, sensing, network
/// options and faults; random node failures off (the nemesis crashes cameras, and every crash
/// recovers before `healed_at`).
config::scenario with_chaos(config::scenario scenario, const chaos_plan& plan,
                            const chaos_settings& settings);

}  // namespace argus::apps
