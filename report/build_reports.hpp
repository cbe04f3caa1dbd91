#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "config/scenario.hpp"
#include "world/station.hpp"

namespace argus::report {

/// What build_reports wrote, and what it left out and why ("plan.png (no scenario.yaml ...)").
struct report_outcome {
  std::vector<std::filesystem::path> written;
  std::vector<std::string> left_out;
};

/// Which of the reports to draw.
struct report_options {
  /// Draw `feeds/` (the cameras' frames at the key events and their contact sheet): it renders,
  /// which the other reports do not, so runs that need no pictures of it (sweeps) leave it out.
  bool feeds = true;
  /// The scenario's station, when the caller has it loaded (argus run, after the run): it is
  /// used as it is, not loaded again. Null: loaded from the scenario's layout (its distance
  /// fields from the field cache when a run has just kept them there).
  std::shared_ptr<const world::station> station;
};

/// (Re)builds a run's reports in its output folder `dir` from the files the run left there
/// (docs/reports.md): plan.png (needs the scenario, for the station and the cameras; target
/// paths from targets.csv when present), timeline.png (from events.jsonl), feeds/ (the scenario,
/// events.jsonl, poses.csv and tracks.csv, and an EGL renderer; report/key_frame_feeds.hpp) and
/// report.html (whatever exists of the above, metrics.json, summary.json and events.jsonl).
/// `scenario` is the run's scenario; when null, `dir/scenario.yaml` is read if it exists.
/// Missing files leave their parts out; throws std::runtime_error only when a report cannot be
/// written.
report_outcome build_reports(const std::filesystem::path& dir,
                             const config::scenario* scenario = nullptr,
                             const report_options& options = {});

}  // namespace argus::report
