#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "config/scenario.hpp"

namespace argus::report {

/// What build_reports wrote, and what it left out and why ("plan.png (no scenario.yaml ...)").
struct report_outcome {
  std::vector<std::filesystem::path> written;
  std::vector<std::string> left_out;
};

/// (Re)builds a run's reports in its output folder `dir` from the files the run left there
/// (docs/reports.md): plan.png (needs the scenario, for the station and the cameras; target
/// paths from targets.csv when present), timeline.png (from events.jsonl) and report.html
/// (whatever exists of the above, metrics.json, summary.json and events.jsonl). `scenario` is
/// the run's scenario; when null, `dir/scenario.yaml` is read if it exists. Missing files
/// leave their parts out; throws std::runtime_error only when a report cannot be written.
report_outcome build_reports(const std::filesystem::path& dir,
                             const config::scenario* scenario = nullptr);

}  // namespace argus::report
