#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "config/scenario.hpp"
#include "world/station.hpp"

namespace argus::apps {

/// What a run leaves in its output folder besides the simulation's own files: the effective
/// scenario (`scenario.yaml`, --set overrides applied, file paths made absolute so the copy
/// loads from anywhere: `argus report` draws the plan from it) and the reports
/// (report/build_reports.hpp), with `feeds/` unless `feeds` is false (`--no-feeds`: then a
/// `feeds/` folder an earlier run left in the folder is removed, as it is not this run's; when
/// the feeds are left out for a reason other than having no key event, stderr says why).
/// Returns report.html's path, or nothing when the reports could not be written (said on
/// stderr: a run that finished is not failed by its pictures).
/// `station` is the scenario's, when the caller has it (the run's, `run_outcome::station`); null:
/// the reports load it.
std::optional<std::filesystem::path> record_run(
    const config::scenario& scenario, const std::filesystem::path& output_dir, bool feeds = true,
    std::shared_ptr<const world::station> station = nullptr);

}  // namespace argus::apps
