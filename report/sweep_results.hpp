#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nlohmann/json.hpp"
#include "report/metric_plot.hpp"

namespace argus::report {

/// A scenario field a sweep varies (`--set key=v1,v2`), values in the order given.
struct swept_parameter {
  std::string key;
  std::vector<std::string> values;
};

/// One run of a sweep: a point of the grid and a seed, and what came of it.
struct sweep_run {
  /// Names its output folder, runs/<id>.
  std::string id;
  /// One value per swept parameter, in the parameters' order.
  std::vector<std::string> values;
  std::uint64_t seed = 0;
  /// The process's exit status; nothing when the run did not happen (interrupted sweep).
  std::optional<int> exit_status;
  /// Wall-clock seconds of the run's process.
  double wall_s = 0.0;
  /// metrics.json's "summary" object; null when the run left none.
  nlohmann::json summary;

  /// The summary's `metric`; nothing where the run has none or it is not a number (null).
  std::optional<double> metric(const std::string& name) const;
};

/// A whole sweep: its grid and every run.
struct sweep_results {
  std::string scenario;
  std::vector<swept_parameter> parameters;
  std::size_t seeds = 0;
  std::vector<sweep_run> runs;
  /// Paired differences within this of 0 count as neither higher nor lower (`--equal-within`).
  double equal_within = 0.0;
  /// The metric the sweep leads with (`--compare`).
  std::string compare = "mean_coverage";

  /// The numeric fields of the runs' summaries, by name.
  std::vector<std::string> metric_names() const;

  /// `metric` at each value of parameter `parameter_index`, over every run that reported it
  /// (all seeds and all values of the other parameters pooled).
  std::vector<metric_point> metric_points(const std::string& metric,
                                          std::size_t parameter_index) const;
};

}  // namespace argus::report
