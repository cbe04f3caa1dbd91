#include "config/duration.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>

namespace argus::config {

namespace {

/// A duration unit and how a count of it converts to seconds. Milliseconds divide rather
/// than multiply by 0.001 so that "200 ms" gives exactly the double nearest to 0.2.
struct duration_unit {
  std::string_view name;
  double factor;
  bool divides;

  double to_seconds(double count) const { return divides ? count / factor : count * factor; }
  double from_seconds(double value) const { return divides ? value * factor : value / factor; }
};

/// Largest unit first: format_duration prefers the largest unit giving a whole number.
constexpr std::array<duration_unit, 4> units{{
    {"h", 3600.0, false},
    {"min", 60.0, false},
    {"s", 1.0, false},
    {"ms", 1000.0, true},
}};

std::string_view trim(std::string_view text) {
  constexpr std::string_view blanks = " \t\r\n";
  const auto first = text.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(blanks);
  return text.substr(first, last - first + 1);
}

/// Parses a whole decimal number (optional sign, optional exponent); nothing may follow.
std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

/// Parses "a" or "a/b".
std::optional<double> parse_count(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return parse_number(text);
  const auto numerator = parse_number(text.substr(0, slash));
  const auto denominator = parse_number(text.substr(slash + 1));
  if (!numerator || !denominator || *denominator == 0.0) return std::nullopt;
  return *numerator / *denominator;
}

/// Doubles beyond 2^53 are not all integers that print exactly; keep whole counts below.
constexpr double max_exact_integer = 9007199254740992.0;

}  // namespace

std::optional<seconds> parse_duration(std::string_view text) {
  text = trim(text);
  const auto unit_begin = text.find_last_not_of("abcdefghijklmnopqrstuvwxyz") + 1;
  const auto unit_name = text.substr(unit_begin);
  const auto count = parse_count(text.substr(0, unit_begin));
  if (!count) return std::nullopt;
  for (const auto& unit : units) {
    if (unit.name != unit_name) continue;
    const double value = unit.to_seconds(*count);
    if (!std::isfinite(value)) return std::nullopt;
    return seconds{value};
  }
  return std::nullopt;
}

std::string format_duration(seconds duration) {
  const double value = duration.count();
  if (value == 0.0) return "0 s";
  if (!std::isfinite(value)) return fmt::format("{} s", value);
  for (const auto& unit : units) {
    const double count = std::round(unit.from_seconds(value));
    if (count != 0.0 && std::abs(count) < max_exact_integer && unit.to_seconds(count) == value) {
      return fmt::format("{} {}", static_cast<long long>(count), unit.name);
    }
  }
  // fmt's default double format is the shortest decimal that reads back exactly.
  auto decimal = fmt::format("{} s", value);
  const double magnitude = std::abs(value);
  if (magnitude < 1.0) {
    const double denominator = std::round(1.0 / magnitude);
    if (denominator < max_exact_integer && 1.0 / denominator == magnitude) {
      auto fraction =
          fmt::format("{}1/{} s", value < 0.0 ? "-" : "", static_cast<long long>(denominator));
      if (fraction.size() < decimal.size()) return fraction;
    }
  }
  return decimal;
}

}  // namespace argus::config
