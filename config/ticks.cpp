#include "config/ticks.hpp"

#include <algorithm>
#include <cmath>

namespace argus::config {

std::int64_t to_ticks(seconds duration, seconds tick) {
  return static_cast<std::int64_t>(std::floor(duration / tick + 0.5 + tick_tolerance));
}

std::int64_t to_ticks_at_least_one(seconds duration, seconds tick) {
  return std::max<std::int64_t>(1, to_ticks(duration, tick));
}

std::int64_t ticks_covering(seconds duration, seconds tick) {
  return static_cast<std::int64_t>(std::ceil(duration / tick - tick_tolerance));
}

std::int64_t ticks_within(seconds duration, seconds tick) {
  return static_cast<std::int64_t>(std::floor(duration / tick + tick_tolerance));
}

seconds to_seconds(std::int64_t ticks, seconds tick) {
  return static_cast<double>(ticks) * tick;
}

}  // namespace argus::config
