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

/// sweep.json: the grid, every run with its whole summary, and per metric and parameter the
/// mean and 95% confidence interval at each value.
nlohmann::json sweep_json(const sweep_results& results);

/// Writes `dir`/sweep.csv, `dir`/sweep.json and `dir`/plots/<metric>_vs_<key>.png for every
/// metric with a value in some run and every parameter with two values or more; returns the
/// files written.
std::vector<std::filesystem::path> write_sweep_outputs(const std::filesystem::path& dir,
                                                       const sweep_results& results);

}  // namespace argus::report
