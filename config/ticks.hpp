#pragma once

// Virtual time in ticks: where scenario durations (seconds) become whole ticks of the
// simulation clock, with one rounding rule. Every conversion from seconds to ticks goes
// through here.
//
//   q = duration / tick                       (ticks, as a real number)
//   to_ticks(duration, tick) = floor(q + 1/2 + ε)   nearest tick, halves round up
//
// ε = tick_tolerance (10⁻⁹ of a tick) absorbs the binary error of the division, so that a
// duration meant to land on a tick boundary or on a half tick does: 200 ms at 1/15 s is 3
// ticks even where 0.2 / (1/15) computes as 2.9999999999999996 or 3.0000000000000004, and
// 1500 ms at 1/15 s (22.5 ticks) is 23 even where the quotient computes a hair under 22.5.
//
// Two named variants round one way on purpose, for bounds that must hold (the link's delay
// range, the timeout after which an answer is late): ticks_covering() and ticks_within(),
// with the same ε. Each caller says next to its named function why it needs them.

#include <cstdint>

#include "config/scenario.hpp"

namespace argus::config {

/// Below this fraction of a tick, a quotient is taken to be on the boundary (or the half).
inline constexpr double tick_tolerance = 1e-9;

/// `duration` in whole ticks of length `tick` (> 0): the nearest, halves rounded up (see the
/// rule above). 500 ms at 1/15 s is 8 ticks (7.5), 1500 ms is 23 (22.5), 2 min is 1800.
std::int64_t to_ticks(seconds duration, seconds tick);

/// to_ticks(), but never less than 1: for a period or a timeout that must take at least one
/// tick (zero would fire every tick, or never wait).
std::int64_t to_ticks_at_least_one(seconds duration, seconds tick);

/// The fewest whole ticks that last at least `duration`: ceil(q - ε). 200 ms at 1/15 s is 3,
/// 210 ms is 4.
std::int64_t ticks_covering(seconds duration, seconds tick);

/// The most whole ticks that fit within `duration`: floor(q + ε). 500 ms at 1/15 s is 7,
/// 1500 ms is 22.
std::int64_t ticks_within(seconds duration, seconds tick);

/// `ticks` ticks of length `tick`, in seconds.
seconds to_seconds(std::int64_t ticks, seconds tick);

}  // namespace argus::config
