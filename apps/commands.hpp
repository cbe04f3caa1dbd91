#pragma once

#include "CLI/CLI.hpp"

namespace argus::apps {

/// Exit codes of the `argus` command line.
enum exit_code : int { ok = 0, run_failed = 1, bad_input = 2 };

/// Adds `argus run` to `app`; its callback sets `result` to the command's exit code.
void add_run_command(CLI::App& app, int& result);

/// Adds `argus plan` to `app`; its callback sets `result` to the command's exit code.
void add_plan_command(CLI::App& app, int& result);

/// Adds `argus crowd` (steps a scenario's crowd alone, no cameras: trajectories,
/// measurement areas, evacuation summary) to `app`; sets `result` to its exit code.
void add_crowd_command(CLI::App& app, int& result);

/// Adds `argus render` (one camera's frame) to `app`; sets `result` to its exit code.
void add_render_command(CLI::App& app, int& result);

/// Adds `argus feeds` (a mosaic of every camera's view) to `app`; sets `result` to its exit code.
void add_feeds_command(CLI::App& app, int& result);

/// Adds `argus vision` (the low-level visual routines: `localize`) to `app`.
void add_vision_command(CLI::App& app, int& result);

/// Adds `argus csp` (conflict resolution: `solve` a file, regenerate `table1`) to `app`.
void add_csp_command(CLI::App& app, int& result);

/// Adds `argus report` (a run's pictures and page) to `app`; sets `result` to its exit code.
void add_report_command(CLI::App& app, int& result);

/// Adds `argus sweep` (a grid of runs over seeds, in parallel) to `app`; sets `result` to its
/// exit code.
void add_sweep_command(CLI::App& app, int& result);

/// Adds `argus chaos` (runs under random faults, each checked for safety and liveness) to
/// `app`; sets `result` to its exit code.
void add_chaos_command(CLI::App& app, int& result);

/// Adds `argus generate station` (a large station's scenario and layout) to `app`; sets
/// `result` to its exit code.
void add_generate_command(CLI::App& app, int& result);

/// Adds `argus serve` (a live run with its operator console in the browser) to `app`; sets
/// `result` to its exit code.
void add_serve_command(CLI::App& app, int& result);

/// Adds `argus strategies` (the strategies controller.strategy can name) to `app`; sets
/// `result` to its exit code.
void add_strategies_command(CLI::App& app, int& result);

/// Adds `argus worker` (hosts camera nodes and links for a distributed run) to `app`; sets
/// `result` to its exit code.
void add_worker_command(CLI::App& app, int& result);
/// Adds `argus validate` to `app`; its callback sets `result` to the command's exit code.
void add_validate_command(CLI::App& app, int& result);

}  // namespace argus::apps
