#include "config/value_bounds.hpp"

#include <fmt/format.h>

namespace argus::config {

bool value_bounds::contains(double value) const {
  if (value != value) return false;  // NaN
  if (min && (min_inclusive ? value < *min : value <= *min)) return false;
  if (max && (max_inclusive ? value > *max : value >= *max)) return false;
  return true;
}

std::string value_bounds::describe(const std::function<std::string(double)>& format) const {
  if (min && max) {
    return fmt::format("in {}{}, {}{}", min_inclusive ? '[' : '(', format(*min), format(*max),
                       max_inclusive ? ']' : ')');
  }
  if (min) return fmt::format("{} {}", min_inclusive ? ">=" : ">", format(*min));
  if (max) return fmt::format("{} {}", max_inclusive ? "<=" : "<", format(*max));
  return {};
}

std::string value_bounds::describe() const {
  return describe([](double value) { return fmt::format("{}", value); });
}

}  // namespace argus::config
