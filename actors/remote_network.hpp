#pragma once

#include <chrono>
#include <functional>
#include <memory>
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
/// How long it waits for a worker's set-up, asked for before the coordinator loads its own
/// station (ask_workers_to_set_up): the worker may wait meanwhile for the coordinator to compute
/// the distance fields they share through the field cache (10 s for the large station on two
/// cores, more on fewer). A worker that does not answer at all was named by greet_workers.
inline constexpr std::chrono::seconds worker_set_up_timeout{120};

/// Checks that every worker runs this Argus version (worker_hello_atom); throws
/// std::runtime_error naming the first that does not answer within `timeout` or differs.
void greet_workers(caf::actor_system& system, const std::vector<worker_contact>& workers,
                   std::chrono::milliseconds timeout);

/// The workers' set-ups, asked for and not yet answered (ask_workers_to_set_up).
class pending_set_up {
 public:
  pending_set_up();
  pending_set_up(pending_set_up&&) noexcept;
  pending_set_up& operator=(pending_set_up&&) noexcept;
  ~pending_set_up();

  struct requests;
  std::unique_ptr<requests> asked;
};

/// Asks every worker to set up its part of the run and returns without waiting: each parses the
/// scenario, loads the station and spawns its links while the coordinator loads its own station
/// and spawns its actors (docs/distributed.md, "Starting a run"). `setup` carries the scenario
/// and its files, and worker w steps crowd partitions when `steps_crowd[w]` (it loads the
/// distance fields); each worker's links are those `place_link` gives it (its first camera's
/// worker, or none when `on_loss` keeps the run going: those are spawned here, by
/// spawn_remote_network); `setup.coordinator` lives as long as the run.
pending_set_up ask_workers_to_set_up(caf::actor_system& system, const config::scenario& scenario,
                                     const protocol::topology& topo,
                                     const std::vector<worker_contact>& workers, worker_setup setup,
                                     worker_loss on_loss = worker_loss::end_run,
                                     const std::vector<bool>& steps_crowd = {});

/// `spawn_network` for a distributed run: the same links and camera nodes, attached and joined
/// to `clock` in the same order, but spawned by the workers, each camera on the worker
/// `place_cameras` gives it (`scenario.placement`) and each link where `place_link` put it.
/// Waits for the set-ups `asked` (ask_workers_to_set_up, with the same scenario, topology and
/// workers) first. The directory's `hosts` says where each camera is, so a camera that recovers
/// from a crash comes back there. Throws std::runtime_error naming the worker that refused or
/// did not answer.
network_directory spawn_remote_network(caf::actor_system& system, const config::scenario& scenario,
                                       const protocol::topology& topo, const caf::actor& clock,
                                       const std::vector<worker_contact>& workers,
                                       pending_set_up asked);

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
