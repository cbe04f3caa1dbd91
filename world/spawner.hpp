#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "world/event.hpp"
#include "world/flow.hpp"
#include "world/pedestrian.hpp"
#include "world/rng.hpp"
#include "world/speed_distribution.hpp"

namespace argus::world {

class station;

/// How the station is kept populated.
struct spawner_settings {
  std::uint64_t run_seed = 1;
  /// Target population.
  unsigned population = 100;
  /// Newcomers per minute while below the target.
  double spawn_rate_per_min = 60.0;
  double tick_s = 1.0 / 15.0;
  /// Where everyone's preferred speed comes from.
  speed_distribution speeds;
  /// How their clothes are coloured.
  config::clothing clothes = config::clothing::palette;
  /// Streams of pedestrians for standard experiments, spawned besides the population.
  std::vector<flow> flows;
};

/// Brings pedestrians in at street portals and up the platform stairs so the population
/// stays at its target. One spawner per world, run once per tick by the world's owner after
/// the partitions stepped (it must see where everyone now stands), with its own RNG: the
/// newcomers depend on the run seed and the merged states only, never on partitioning.
/// Ids are 1, 2, 3, ... in order of creation and never reused.
class spawner {
 public:
  /// Seeds its RNG with config::derive_seed(run_seed, a fixed stream tag).
  explicit spawner(spawner_settings settings);

  /// The initial crowd: `population` pedestrians at random free spots of the walking floor,
  /// so a run starts in a steady state instead of an empty station. Appends `spawned`
  /// events for `tick`.
  std::vector<pedestrian> populate(const station& where, std::uint64_t tick,
                                   std::vector<event>& events);

  /// Newcomers for `tick`, placed where no one in `present` stands: first each flow's (all
  /// at once, or rate_per_s from start_s on, until its count is reached; a spot taken
  /// delays them), then the station's, accumulating spawn_rate_per_min per tick while below
  /// the target population; a blocked portal delays them.
  std::vector<pedestrian> spawn(const station& where, std::span<const pedestrian_state> present,
                                std::uint64_t tick, std::vector<event>& events);

  /// The id the next newcomer gets.
  int next_id() const noexcept { return next_id_; }

  /// Pedestrians flow `index` has brought in so far.
  unsigned flow_spawned(std::size_t index) const { return flow_spawned_[index]; }

 private:
  bool place(const station& where, std::span<const pedestrian_state> present,
             const std::vector<pedestrian>& fresh, std::uint64_t tick, std::vector<pedestrian>& out,
             std::vector<event>& events);

  spawner_settings settings_;
  rng random_;
  int next_id_ = 1;
  double credit_ = 0.0;
  std::vector<unsigned> flow_spawned_;
  std::vector<double> flow_credit_;
};

}  // namespace argus::world
