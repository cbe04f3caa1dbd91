#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>

#include "actors/run_result.hpp"
#include "actors/worker_loss.hpp"
#include "config/scenario.hpp"
#include "eval/metrics.hpp"
#include "live/session.hpp"
#include "world/station.hpp"

namespace argus::actors {

/// What `argus run` produced: the run's figures and where its files went.
struct run_outcome {
  run_result result;
  std::filesystem::path output_dir;
  /// The run measured against ground truth (also in metrics.json).
  eval::evaluation evaluation;
  /// The station the run ran in, with its distance fields: the reports draw and walk the crowd
  /// in it rather than load it again.
  std::shared_ptr<const world::station> station;
};

/// How `argus run` runs a scenario, beyond the scenario itself.
struct run_options {
  /// Print a progress line (stderr) while running.
  bool show_progress = false;
  /// Write a mosaic video of every camera's degraded view, one frame per tick, to
  /// `<output dir>/video/feeds.avi` (render pool + video recorder).
  bool video = false;
  /// Size of one camera's tile in the video, pixels.
  int video_width_px = 320;
  int video_height_px = 240;
  /// Renderers (EGL contexts) for pixel sensing, and render workers for the video; 0 = as many
  /// as scheduler threads.
  std::size_t render_threads = 0;
  /// Also write the run in MOTChallenge format to `<output dir>/mot` (ground truth of every
  /// camera's every frame: a visibility pass per camera per frame).
  bool mot = false;
  /// A live run (argus serve): the operator's commands come in through it, its pacing replaces
  /// `run.speed`, and the run shows itself on its console. Null for none.
  std::shared_ptr<live::session> live;
  /// The scenario's station when the caller has loaded it already (argus serve); null: load it.
  std::shared_ptr<const world::station> station;
  /// A distributed run (docs/distributed.md): the workers that host the camera nodes and their
  /// links. Null: everything runs in this process, and no network layer is loaded.
  std::shared_ptr<const class worker_pool> workers;
  /// What losing one of `workers` mid-run does (`--on-worker-loss`).
  worker_loss on_worker_loss = worker_loss::end_run;
};

/// Runs a validated scenario to its end on a CAF scheduler with `scenario.run.threads` worker
/// threads (0 = one per hardware thread): spawns the clock, the recorder, one link per pair of
/// neighbours, one camera node per camera, the scenario script and the fault injector, and
/// waits for the clock. Throws std::runtime_error when the
/// run cannot complete (e.g. the output directory is not writable, or no EGL device works
/// for `--video`). With `options.video`, also spawns a render pool and the video recorder.
run_outcome run_scenario(const config::scenario& scenario, const run_options& options);

/// The station of `scenario`'s layout as a run loads it: its distance fields from the field cache
/// when a run has kept them there (and kept there when computed), on `run.threads` threads.
/// Throws as world::station::load does.
std::shared_ptr<const world::station> load_run_station(const config::scenario& scenario);

/// The same without video.
run_outcome run_scenario(const config::scenario& scenario, bool show_progress);

/// The output directory a scenario's run writes to: `run.output_dir`, or `out/<name>`.
std::filesystem::path output_dir_of(const config::scenario& scenario);

/// Where the scenario's emulated-sensor model file is (relative paths are taken from the
/// scenario file's folder).
std::filesystem::path sensor_model_path(const config::scenario& scenario);

}  // namespace argus::actors
