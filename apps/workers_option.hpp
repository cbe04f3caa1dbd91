#pragma once

#include <optional>
#include <string>

#include "CLI/CLI.hpp"
#include "actors/run_scenario.hpp"
#include "apps/tls_options.hpp"

namespace argus::apps {

/// Where a run's cameras go, as given on the command line: `--workers` and `--on-worker-loss`
/// (docs/distributed.md), for `argus run` and `argus serve`.
struct workers_arguments {
  std::optional<std::string> workers;
  std::string on_worker_loss = "end-run";
};

/// Adds --workers and --on-worker-loss to `cmd`.
void add_workers_options(CLI::App* cmd, workers_arguments& args);

/// Sets `options.workers` (null: this process alone) and `options.on_worker_loss` from `args`,
/// connecting with the TLS identity `tls`. Throws std::invalid_argument naming the option for
/// --on-worker-loss without --workers, and, when `tls_only_for_workers` (argus run: the TLS
/// options have no other use), for TLS options without --workers.
void apply_workers_options(const workers_arguments& args, const tls_arguments& tls,
                           bool tls_only_for_workers, actors::run_options& options);

}  // namespace argus::apps
