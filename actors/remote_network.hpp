#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "actors/fault_injector.hpp"
#include "actors/wire_live.hpp"
#include "actors/worker_loss.hpp"
#include "actors/worker_placement.hpp"
#include "actors/worker_protocol.hpp"
#include "caf/actor.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"
#include "eval/observation_log.hpp"
#include "protocol/topology.hpp"

namespace argus::actors {

/// A worker as the coordinator reaches it: its name (HOST:PORT) and the actor that hosts its
/// part of the run (spawn_worker_host, a proxy when it is in another process).
struct worker_contact {
  std::string name;
  caf::actor host;
};

/// How long a coordinator waits for a worker's answer while a run is set up.
inline constexpr std::chrono::seconds worker_setup_timeout{30};

/// Checks that every worker runs this Argus version (worker_hello_atom); throws
/// std::runtime_error naming the first that does not answer within `timeout` or differs.
void greet_workers(caf::actor_system& system, const std::vector<worker_contact>& workers,
                   std::chrono::milliseconds timeout);

/// `spawn_network` for a distributed run: the same links and camera nodes, attached and joined
/// to `clock` in the same order, but spawned by the workers, each camera on the worker
/// `place_cameras` gives it (`scenario.placement`) and each link where `place_link` puts it
/// (its first camera's worker, or here when `on_loss` keeps the run going). `setup`
/// carries the scenario and its files, and worker w steps crowd partitions when `steps_crowd[w]`
/// (it loads the distance fields); `anchor` lives as long as the run. The directory's `hosts`
/// says where each camera is, so a camera that recovers from a crash comes back there. Throws
/// std::runtime_error naming the worker that refused or did not answer.
network_directory spawn_remote_network(caf::actor_system& system, const config::scenario& scenario,
                                       const protocol::topology& topo, const caf::actor& clock,
                                       const std::vector<worker_contact>& workers,
                                       worker_setup setup,
                                       worker_loss on_loss = worker_loss::end_run,
                                       const std::vector<bool>& steps_crowd = {});

/// Once the run is over: hands what a live run's console has not yet shown of every worker's
/// cameras (their last tick's turns) to `shown`, when set, adds what they recorded to `log`, and
/// tells each worker to end what it hosted. A worker that does not answer within `timeout` is
/// skipped with a warning (the run has already failed when that happens, or, when the workers
/// `streamed` their logs every tick, went on without it).
void finish_workers(caf::actor_system& system, const std::vector<worker_contact>& workers,
                    eval::observation_log& log, std::chrono::milliseconds timeout,
                    bool streamed = false,
                    const std::function<void(live_display)>& shown = nullptr);

}  // namespace argus::actors
