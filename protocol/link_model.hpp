#pragma once

#include <cstdint>
#include <random>

#include "config/scenario.hpp"
// PCG (Debian's libpcg-cpp-dev): 32 bytes of state where mt19937_64 has 2.5 KB. Every link
// direction owns one, so with tens of thousands of links the generators' state alone outgrew
// the caches (bench/RESULTS.md, "Link layer").
#include "pcg_random.hpp"

namespace argus::protocol {

/// What happens to one message on a link.
struct link_fate {
  bool lost = false;
  /// Ticks from sending to delivery (>= 1: delivery is on a later tick boundary).
  std::int64_t delay_ticks = 1;
  /// A second copy arrives too (scenario `duplicate_probability`).
  bool duplicated = false;
  std::int64_t duplicate_delay_ticks = 1;
};

/// The random behaviour of a link (Table 2): loss with probability `loss_probability`, delay
/// uniform in [min_delay, max_delay] delivered on the nearest tick boundary within those
/// bounds (200-500 ms at 15 Hz: 3 to 7 ticks), optional duplication.
///
/// The parameters only: the random stream is the caller's (one per link direction, seeded
/// from the run seed and the link's id), so that one model serves every link of a network and
/// stays in cache while tens of thousands of links draw from it.
class link_model {
 public:
  link_model(const config::network_settings& network, double tick_seconds);

  /// Draws the fate of one message from `rng`; `loss_probability` overrides the scenario's
  /// (loss bursts).
  link_fate draw(pcg64& rng, double loss_probability) const;

  /// The fewest ticks any message spends on a link of this network: the links' lookahead
  /// (what is sent at tick t is never due before t + min_delay_ticks).
  static std::int64_t min_delay_ticks(const config::network_settings& network, double tick_seconds);

  /// Draws with the scenario's loss probability.
  link_fate draw(pcg64& rng) const { return draw(rng, loss_); }

  /// The scenario's loss probability.
  double loss() const noexcept { return loss_; }

 private:
  // The most ticks any message spends on a link of this network (never below
  // `lowest_ticks`, the min_delay_ticks()).
  static std::int64_t max_delay_ticks(const config::network_settings& network, double tick_seconds,
                                      std::int64_t lowest_ticks);
  std::int64_t draw_delay_ticks(pcg64& rng) const;

  double loss_;
  double duplicate_;
  double min_delay_s_;
  double max_delay_s_;
  double tick_s_;
  // The delay bounds in whole ticks, at least 1 (a draw is rounded to the nearest tick within
  // them).
  std::int64_t lowest_ticks_;
  std::int64_t highest_ticks_;
};

}  // namespace argus::protocol
