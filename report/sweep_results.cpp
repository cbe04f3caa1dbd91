#include "report/sweep_results.hpp"

#include <set>

namespace argus::report {

std::optional<double> sweep_run::metric(const std::string& name) const {
  if (!summary.is_object()) return std::nullopt;
  const auto it = summary.find(name);
  if (it == summary.end() || !it->is_number()) return std::nullopt;
  return it->get<double>();
}

std::vector<std::string> sweep_results::metric_names() const {
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const auto& run : runs) {
    if (!run.summary.is_object()) continue;
    for (const auto& [key, value] : run.summary.items())
      if ((value.is_number() || value.is_null()) && seen.insert(key).second) out.push_back(key);
  }
  return out;
}

std::vector<metric_point> sweep_results::metric_points(const std::string& metric,
                                                       std::size_t parameter_index) const {
  std::vector<metric_point> out;
  for (const auto& value : parameters.at(parameter_index).values) {
    std::vector<double> sample;
    for (const auto& run : runs)
      if (run.values.at(parameter_index) == value)
        if (const auto m = run.metric(metric)) sample.push_back(*m);
    out.push_back({value, mean_with_ci95(sample)});
  }
  return out;
}

}  // namespace argus::report
