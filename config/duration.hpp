#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "config/scenario.hpp"

namespace argus::config {

/// Parses a duration written with a unit: "1500 ms", "1500ms", "1.5 s", "1/15 s", "2 min",
/// "1 h". Units are ms, s, min and h; the number may be a decimal (with exponent) or a
/// fraction a/b. A bare number is rejected because "1500" could mean seconds or
/// milliseconds. Returns nullopt for anything else, including non-finite values.
std::optional<seconds> parse_duration(std::string_view text);

/// Writes `duration` in the most readable form that `parse_duration` reads back to exactly
/// the same value: a whole number of the largest unit that fits ("2 min", "90 s",
/// "1500 ms"), else the shorter of a fraction "1/N s" and the shortest round-trip decimal
/// in seconds ("0.0005 s").
std::string format_duration(seconds duration);

}  // namespace argus::config
