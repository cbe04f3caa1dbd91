#include "protocol/link_model.hpp"

#include <algorithm>
#include <cmath>

namespace argus::protocol {

link_model::link_model(const config::network_settings& network, double tick_seconds)
    : loss_(network.loss_probability),
      duplicate_(network.duplicate_probability),
      min_delay_s_(network.min_delay.count()),
      max_delay_s_(network.max_delay.count()),
      tick_s_(tick_seconds),
      lowest_ticks_(min_delay_ticks(network, tick_seconds)),
      highest_ticks_(std::max(
          lowest_ticks_, static_cast<std::int64_t>(std::floor(max_delay_s_ / tick_s_ + 1e-9)))) {}

std::int64_t link_model::min_delay_ticks(const config::network_settings& network,
                                         double tick_seconds) {
  // 1e-9 absorbs binary fractions such as 0.2 / (1/15) = 3.0000000000000004.
  auto lowest =
      static_cast<std::int64_t>(std::ceil(network.min_delay.count() / tick_seconds - 1e-9));
  return std::max<std::int64_t>(1, lowest);
}

std::int64_t link_model::draw_delay_ticks(pcg64& rng) const {
  double delay = min_delay_s_;
  if (max_delay_s_ > min_delay_s_)
    delay = std::uniform_real_distribution<double>(min_delay_s_, max_delay_s_)(rng);
  // Delivered on the nearest tick boundary (unbiased on average), kept within the bounds:
  // never earlier than min_delay, never later than max_delay.
  auto ticks = static_cast<std::int64_t>(std::llround(delay / tick_s_));
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
