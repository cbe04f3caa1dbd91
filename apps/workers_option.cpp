#include "apps/workers_option.hpp"

#include <memory>
#include <stdexcept>

#ifdef ARGUS_WITH_DISTRIBUTED
#include "distributed/network_workers.hpp"
#endif

namespace argus::apps {

void add_workers_options(CLI::App* cmd, workers_arguments& args) {
  cmd->add_option("--workers", args.workers,
                  "Run the cameras and their links on these workers (argus worker), "
                  "HOST:PORT,...; placement.policy says how (docs/distributed.md)");
  cmd->add_option("--on-worker-loss", args.on_worker_loss,
                  "What a worker lost mid-run does: end-run (the run ends with its last whole "
                  "tick, exit 1) or crash-nodes (its cameras become crashed nodes and the run "
                  "goes on); see docs/distributed.md")
      ->check(CLI::IsMember({"end-run", "crash-nodes"}));
}

void apply_workers_options(const workers_arguments& args, const tls_arguments& tls,
                           bool tls_only_for_workers, actors::run_options& options) {
  if (!args.workers) {
    if (tls_only_for_workers && tls.given())
      throw std::invalid_argument("--tls-cert, --tls-key and --tls-ca are for --workers");
    if (args.on_worker_loss == "crash-nodes")
      throw std::invalid_argument("--on-worker-loss is for --workers");
    options.workers = nullptr;
    return;
  }
#ifdef ARGUS_WITH_DISTRIBUTED
  options.workers = std::make_shared<distributed::network_workers>(
      distributed::parse_endpoints(*args.workers, "--workers"),
      distributed::tls_files{tls.cert, tls.key, tls.ca});
  if (args.on_worker_loss == "crash-nodes")
    options.on_worker_loss = actors::worker_loss::crash_nodes;
#else
  (void)tls;
  throw std::invalid_argument("--workers: this build has no network layer (libcaf-io)");
#endif
}

}  // namespace argus::apps
