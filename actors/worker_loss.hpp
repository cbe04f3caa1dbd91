#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace argus::actors {

/// What a distributed run does when it loses a worker (docs/distributed.md, "A lost worker").
enum class worker_loss : std::uint8_t {
  /// The run ends with its last whole tick, its outputs complete up to it, and fails naming
  /// the worker: what was written is what one process writes, as far as it goes.
  end_run = 0,
  /// The worker's cameras become crashed nodes and the run goes on (`--on-worker-loss
  /// crash-nodes`): the paper's protocol is built to survive node failures. From the tick of
  /// the loss the run is no longer the one a single process would have run.
  crash_nodes = 1,
};

/// The clock's word to the fault injector that a worker is gone with the participants it
/// hosted (their participant ids): under `worker_loss::crash_nodes`, the injector takes its
/// cameras down at its next turn as it takes down a crashed camera.
struct lost_worker {
  std::string host;
  std::int64_t tick = 0;
  std::vector<std::uint64_t> participants;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, lost_worker& x) {
  return f(x.host, x.tick, x.participants);
}

}  // namespace argus::actors
