#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "nlohmann/json.hpp"
#include "report/sweep_results.hpp"

namespace argus::report {

/// sweep.csv (docs/sweep.md): one row per run: `run`, each swept key, `seed`, `exit_status`
/// (empty for a run not done), `wall_s`, then every numeric field of the runs' metrics.json
/// summaries (empty where a run has none or it is null).
std::string sweep_csv(const sweep_results& results);

/// paired.csv (docs/sweep.md): for every metric, every parameter with two values or more and
/// each of its values after the first, the paired difference against the first
/// (paired_differences.hpp): `metric,parameter,value,baseline,pairs,mean_difference,
/// standard_error,ci95_low,ci95_high,higher,lower,equal,sign_test_p` (empty where undefined).
std::string paired_csv(const sweep_results& results);

/// sweep.json: the grid, every run with its whole summary, per metric and parameter the mean
/// and 95% confidence interval at each value (`statistics`), and the paired differences of
/// paired.csv (`paired`).
nlohmann::json sweep_json(const sweep_results& results);

/// Writes `dir`/sweep.csv, `dir`/sweep.json, `dir`/paired.csv, for every metric with a value
/// in some run and every parameter with two values or more `dir`/plots/<metric>_vs_<key>.png
/// and, where some pair has the metric, <metric>_vs_<key>_paired.png, and last `dir`/sweep.html
/// (sweep_page.hpp); returns the files written.
std::vector<std::filesystem::path> write_sweep_outputs(const std::filesystem::path& dir,
                                                       const sweep_results& results);

}  // namespace argus::report
