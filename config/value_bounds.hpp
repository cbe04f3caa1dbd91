#pragma once

#include <functional>
#include <optional>
#include <string>

namespace argus::config {

/// The allowed range of a numeric scenario value; either end may be open, closed or absent.
/// It both checks a value and says in words what was expected ("in [0, 1]", "> 0").
struct value_bounds {
  /// Lower end; none = unbounded below.
  std::optional<double> min;
  /// Whether `min` itself is allowed ([) or not (().
  bool min_inclusive = true;
  /// Upper end; none = unbounded above.
  std::optional<double> max;
  /// Whether `max` itself is allowed (]) or not ()).
  bool max_inclusive = true;

  /// Any value (only finiteness is checked by the readers).
  static value_bounds any() { return {}; }
  /// x >= low.
  static value_bounds at_least(double low) { return {low, true, std::nullopt, true}; }
  /// x > low.
  static value_bounds above(double low) { return {low, false, std::nullopt, true}; }
  /// x <= high.
  static value_bounds at_most(double high) { return {std::nullopt, true, high, true}; }
  /// low <= x <= high.
  static value_bounds closed(double low, double high) { return {low, true, high, true}; }
  /// low < x < high.
  static value_bounds open(double low, double high) { return {low, false, high, false}; }
  /// low <= x < high.
  static value_bounds right_open(double low, double high) { return {low, true, high, false}; }
  /// low < x <= high.
  static value_bounds left_open(double low, double high) { return {low, false, high, true}; }

  /// Whether `value` lies within the bounds (NaN never does).
  bool contains(double value) const;

  /// The bounds in words, e.g. "in [0, 1]", "> 0", ">= 1"; empty when unbounded. `format`
  /// writes one end, so durations can read "in (0 s, 1 s]".
  std::string describe(const std::function<std::string(double)>& format) const;

  /// `describe` with plain numbers.
  std::string describe() const;
};

}  // namespace argus::config
