#include "report/confidence_interval.hpp"

#include <array>
#include <cmath>

namespace argus::report {

namespace {

// t(0.975, df) for df = 1..30 (any statistics table).
constexpr std::array<double, 30> table{12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306,
                                       2.262,  2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120,
                                       2.110,  2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
                                       2.060,  2.056, 2.052, 2.048, 2.045, 2.042};

// Beyond the table: (df, t) points, the last one df = infinity, joined linearly in 1/df.
struct tail_point {
  double inverse_df;
  double t;
};
constexpr std::array<tail_point, 5> tail{
    {{1.0 / 30, 2.042}, {1.0 / 40, 2.021}, {1.0 / 60, 2.000}, {1.0 / 120, 1.980}, {0.0, 1.960}}};

}  // namespace

double t_quantile_975(std::size_t degrees_of_freedom) {
  if (degrees_of_freedom == 0) degrees_of_freedom = 1;
  if (degrees_of_freedom <= table.size()) return table[degrees_of_freedom - 1];
  const double x = 1.0 / static_cast<double>(degrees_of_freedom);
  for (std::size_t k = 1; k < tail.size(); ++k) {
    if (x >= tail[k].inverse_df) {
      const auto& a = tail[k - 1];
      const auto& b = tail[k];
      return b.t + (a.t - b.t) * (x - b.inverse_df) / (a.inverse_df - b.inverse_df);
    }
  }
  return tail.back().t;
}

mean_interval mean_with_ci95(std::span<const double> values) {
  mean_interval out;
  out.count = values.size();
  if (values.empty()) return out;
  double sum = 0.0;
  for (double v : values) sum += v;
  out.mean = sum / static_cast<double>(values.size());
  if (values.size() < 2) return out;
  double squares = 0.0;
  for (double v : values) squares += (v - out.mean) * (v - out.mean);
  const double n = static_cast<double>(values.size());
  const double standard_deviation = std::sqrt(squares / (n - 1.0));
  out.standard_error = standard_deviation / std::sqrt(n);
  out.half_width = t_quantile_975(values.size() - 1) * *out.standard_error;
  return out;
}

}  // namespace argus::report
