#include "config/ticks.hpp"

#include <algorithm>
#include <cmath>

namespace argus::config {

std::int64_t to_ticks(seconds duration, seconds tick) {
  // A relative tolerance keeps 1500 ms at 1/15 s (22.5 ticks) from rounding either way by
  // floating-point error.
  const double ticks = duration / tick;
  return static_cast<std::int64_t>(std::floor(ticks + 0.5 + 1e-9 * std::abs(ticks)));
}

std::int64_t to_ticks_at_least_one(seconds duration, seconds tick) {
  return std::max<std::int64_t>(1, to_ticks(duration, tick));
}

}  // namespace argus::config
