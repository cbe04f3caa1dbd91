#pragma once

#include <optional>
#include <span>

namespace argus::report {

/// The mean of a sample and its 95% confidence interval from Student's t-distribution:
/// mean +- t(0.975, n-1) * s / sqrt(n), s the sample standard deviation.
struct mean_interval {
  std::size_t count = 0;
  double mean = 0.0;
  /// The interval's half width; nothing for a sample of one (no spread to estimate).
  std::optional<double> half_width;
  /// s / sqrt(n), the standard error of the mean; nothing for a sample of one.
  std::optional<double> standard_error;

  /// The mean; nothing for an empty sample.
  std::optional<double> defined_mean() const {
    if (count == 0) return std::nullopt;
    return mean;
  }
  /// The interval's ends; nothing for a sample of one or none.
  std::optional<double> low() const {
    if (!half_width) return std::nullopt;
    return mean - *half_width;
  }
  std::optional<double> high() const {
    if (!half_width) return std::nullopt;
    return mean + *half_width;
  }
};

/// mean_interval of `values`; count 0 and mean 0 for an empty sample.
mean_interval mean_with_ci95(std::span<const double> values);

/// The two-sided 95% quantile of Student's t with `degrees_of_freedom` (>= 1): tabulated to
/// 30, interpolated in 1/df beyond it, tending to the normal's 1.96.
double t_quantile_975(std::size_t degrees_of_freedom);

}  // namespace argus::report
