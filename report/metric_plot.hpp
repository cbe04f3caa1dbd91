#pragma once

#include <string>
#include <vector>

#include "report/confidence_interval.hpp"

namespace argus::report {

/// One x position of a metric plot: a swept parameter's value and the metric over its runs.
struct metric_point {
  /// The value as the sweep gave it (`0.2`, `all_solv`).
  std::string value;
  mean_interval metric;
};

/// A metric against one swept parameter, titled `title`: the mean at each value joined by a
/// line, its 95% confidence interval as an error bar, n beside it. The x axis is numeric when
/// every value is a number, else categorical in the order given. Values with no runs are left
/// out. Returns PNG bytes.
std::vector<unsigned char> render_metric_plot(const std::string& title,
                                              const std::string& parameter,
                                              const std::vector<metric_point>& points);

}  // namespace argus::report
