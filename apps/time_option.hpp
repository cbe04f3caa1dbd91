#pragma once

#include <charconv>
#include <cmath>
#include <optional>
#include <string>

#include "config/duration.hpp"

namespace argus::apps {

/// Reads a time option: a duration with a unit ("90 s", "2 min") or a bare number of seconds,
/// as users type both on a command line; nullopt when it is neither, or negative.
inline std::optional<double> seconds_of(const std::string& text) {
  if (auto d = config::parse_duration(text)) {
    if (d->count() < 0.0) return std::nullopt;
    return d->count();
  }
  double value = 0.0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value) || value < 0.0)
    return std::nullopt;
  return value;
}

}  // namespace argus::apps
