#include "protocol/link_model.hpp"

#include <algorithm>

#include "config/ticks.hpp"

namespace argus::protocol {

link_model::link_model(const config::network_settings& network, double tick_seconds)
    : loss_(network.loss_probability),
      duplicate_(network.duplicate_probability),
      min_delay_s_(network.min_delay.count()),
      max_delay_s_(network.max_delay.count()),
      tick_s_(tick_seconds),
      lowest_ticks_(min_delay_ticks(network, tick_seconds)),
      highest_ticks_(max_delay_ticks(network, tick_seconds, lowest_ticks_)) {}

std::int64_t link_model::min_delay_ticks(const config::network_settings& network,
                                         double tick_seconds) {
  // Rounded up, not to the nearest tick: this is the lookahead, so it must never exceed the
  // smallest delay a message actually gets, and a message is never delivered earlier than
  // min_delay (200 ms at 1/15 s: 3 ticks; 210 ms: 4). At least 1: delivery is on a later
  // tick.
  return std::max<std::int64_t>(
      1, config::ticks_covering(network.min_delay, config::seconds{tick_seconds}));
}

std::int64_t link_model::max_delay_ticks(const config::network_settings& network,
                                         double tick_seconds, std::int64_t lowest_ticks) {
  // Rounded down, not to the nearest tick: a message is never delivered later than max_delay
  // (500 ms at 1/15 s: 7 ticks, not 8); never below the lowest, when both bounds fall between
  // the same two ticks.
  return std::max(lowest_ticks,
                  config::ticks_within(network.max_delay, config::seconds{tick_seconds}));
}

std::int64_t link_model::draw_delay_ticks(pcg64& rng) const {
  double delay = min_delay_s_;
  if (max_delay_s_ > min_delay_s_)
    delay = std::uniform_real_distribution<double>(min_delay_s_, max_delay_s_)(rng);
  // Delivered on the nearest tick boundary (unbiased on average), kept within the bounds:
  // never earlier than min_delay, never later than max_delay.
  const auto ticks = config::to_ticks(config::seconds{delay}, config::seconds{tick_s_});
  return std::clamp(ticks, lowest_ticks_, highest_ticks_);  // lowest_ticks_ >= 1
}

link_fate link_model::draw(pcg64& rng, double loss_probability) const {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  link_fate fate;
  // Every draw is made whatever the outcome, so one message's fate never shifts another's.
  fate.lost = unit(rng) < loss_probability;
  fate.delay_ticks = draw_delay_ticks(rng);
  fate.duplicated = unit(rng) < duplicate_;
  fate.duplicate_delay_ticks = draw_delay_ticks(rng);
  return fate;
}

}  // namespace argus::protocol
