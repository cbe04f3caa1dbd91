#pragma once

// Checks on numeric command-line options. CLI11 runs an option's validators on the text the
// user typed before converting it, so a value that passes one of these always converts; the
// message a failed check returns becomes "--option: expected ..., got '...'" and `argus` exits
// with apps::bad_input (apps/main.cpp).

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

#include "CLI/CLI.hpp"
#include "fmt/format.h"

namespace argus::apps {

/// An integer option in [lowest, highest], e.g. `--threads` in [0, 256].
inline CLI::Validator integer_in(std::int64_t lowest, std::int64_t highest) {
  return CLI::Validator(
      [lowest, highest](const std::string& text) -> std::string {
        std::int64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc{} && end == text.data() + text.size() && value >= lowest &&
            value <= highest)
          return {};
        return fmt::format("expected an integer from {} to {}, got '{}'", lowest, highest, text);
      },
      fmt::format("INT in [{} - {}]", lowest, highest));
}

/// A whole-number option of 64 bits, e.g. a seed.
inline CLI::Validator whole_number() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc{} && end == text.data() + text.size()) return {};
        return fmt::format("expected a whole number from 0 to {}, got '{}'", UINT64_MAX, text);
      },
      "UINT");
}

/// A real-number option in [lowest, highest]; `above_lowest` excludes `lowest` itself.
inline CLI::Validator number_in(double lowest, double highest, bool above_lowest = false) {
  return CLI::Validator(
      [lowest, highest, above_lowest](const std::string& text) -> std::string {
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc{} && end == text.data() + text.size() && std::isfinite(value) &&
            (above_lowest ? value > lowest : value >= lowest) && value <= highest)
          return {};
        std::string range;
        if (std::isinf(highest))
          range = fmt::format("{} {}", above_lowest ? "above" : "of at least", lowest);
        else if (above_lowest)
          range = fmt::format("above {} and at most {}", lowest, highest);
        else
          range = fmt::format("from {} to {}", lowest, highest);
        return fmt::format("expected a number {}, got '{}'", range, text);
      },
      "NUMBER");
}

}  // namespace argus::apps
