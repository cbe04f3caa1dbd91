#pragma once

#include <filesystem>

#include "actors/run_result.hpp"
#include "config/scenario.hpp"

namespace argus::actors {

/// What `argus run` produced: the run's figures and where its files went.
struct run_outcome {
  run_result result;
  std::filesystem::path output_dir;
};

/// Runs a validated scenario to its end on a CAF scheduler with `scenario.run.threads` worker
/// threads (0 = one per hardware thread): spawns the clock, the recorder, one link per pair of
/// neighbours, one camera node per camera, the scenario script and the fault injector, and
/// waits for the clock. Throws std::runtime_error when the
/// run cannot complete (e.g. the output directory is not writable).
run_outcome run_scenario(const config::scenario& scenario, bool show_progress);

/// The output directory a scenario's run writes to: `run.output_dir`, or `out/<name>`.
std::filesystem::path output_dir_of(const config::scenario& scenario);

}  // namespace argus::actors
