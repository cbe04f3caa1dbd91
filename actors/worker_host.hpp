#pragma once

#include <cstddef>
#include <string>

#include "caf/fwd.hpp"

namespace argus::actors {

/// The Argus version a coordinator and its workers must share: the same code steps the same
/// world, so a run stays the same to the byte only between equal versions.
const char* argus_version();

/// Spawns the actor that hosts a worker's part of a distributed run (docs/distributed.md);
/// `argus worker` publishes it, tests spawn it in-process. `name` is how it introduces itself;
/// `render_threads` the renderers it makes for pixel sensing; `field_threads` the threads that
/// compute the station's distance fields when it steps crowd partitions (0: one per core).
///
/// Ended (an exit message), it ends the cameras and links it hosts with the same reason, so a
/// host ended with `remote_link_unreachable` in one process looks to the coordinator like a
/// worker lost over the network (tests/actors/distributed_test.cpp).
///
/// `(listening_atom, std::string name)` renames it: `argus worker --listen HOST:0` learns its
/// port only once it has published the host.
///
/// One run at a time. In the order a coordinator sends them:
/// - `(worker_hello_atom, std::string version)` -> `(std::string version, std::string name)`, or
///   an error naming both versions when they differ;
/// - `(worker_setup_atom, worker_setup)` -> `std::vector<caf::actor>`: it reads the scenario and
///   the station from the setup's text, makes what its cameras sense with (the station, a
///   snapshot board, renderers when sensing is pixels, the instruments with an observation log
///   of its own) and spawns the setup's links; answers their handles in the setup's order;
/// - `(spawn_cameras_atom, std::vector<camera_placement>)` -> `std::vector<caf::actor>`: spawns
///   those camera nodes attached to their links (also for a camera that recovers from a crash);
/// - `(spawn_partition_atom, partition_placement)` -> `caf::actor`: spawns a crowd partition that
///   reads its worker's board (a setup with `steps_crowd`, which loaded the distance fields);
/// - every tick, what its cameras did since it was last asked (`worker_gather`: the picks its
///   cameras made, by task, with `--video` each camera's latest pose, and in a live run what the
///   console shows of them): with its answer to the clock in phase world, `(std::vector<tick_ack>,
///   worker_gather)`, or, when it had nothing to tick in phase world, in phase network as the
///   answer to `(gather_atom)`; then, in a live run, `(operator_orders_atom,
///   std::vector<operator_order>)` (no answer): the operator's new orders, onto the operator board
///   its cameras read; then `(board_atom, serialized_delta, std::vector<eval::task_origin> picks)`
///   -> `done_atom`: the picks of every worker join its log, and the world's new snapshot, rebuilt
///   from the last one and the delta, its board, before its cameras' turns; an error when the delta
///   does not fit the last snapshot;
/// - `(take_log_atom)` -> `eval::observation_log::contents`: what its cameras recorded;
/// - `(release_atom)` -> `done_atom`: ends what it hosted and waits for the next run.
caf::actor spawn_worker_host(caf::actor_system& system, std::string name,
                             std::size_t render_threads, unsigned field_threads = 0);

}  // namespace argus::actors
