#pragma once

#include <cstdint>

#include "config/scenario.hpp"

namespace argus::config {

/// The number of ticks of length `tick` in `duration`, rounded to the nearest whole tick
/// (halves up).
std::int64_t to_ticks(seconds duration, seconds tick);

/// to_ticks(), but at least one tick: for periods and timeouts, which must not be zero.
std::int64_t to_ticks_at_least_one(seconds duration, seconds tick);

}  // namespace argus::config
