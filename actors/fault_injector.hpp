#pragma once

#include <map>
#include <string>
#include <utility>

#include "actors/camera_node.hpp"
#include "actors/participant_info.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"
#include "live/session.hpp"

namespace argus::actors {

/// Everything the fault injector acts on: the camera actors and every camera's links.
struct network_directory {
  std::map<int, caf::actor> cameras;
  /// Each camera's links, by neighbour id.
  std::map<int, link_directory> links;
  /// What a camera senses with (a recovered camera gets the same); null for none.
  std::shared_ptr<const camera_world> world;
  /// A distributed run's worker hosts by camera (actors/worker_host.hpp): a camera that
  /// recovers from a crash is spawned again by its own. Empty when everything is local.
  std::map<int, caf::actor> hosts;
  /// The hosts' names by camera, for the clock (participant_info::host).
  std::map<int, std::string> host_names;
};

/// The exit reason of a crash the injector causes. Not `exit_reason::kill`, which an actor
/// cannot intercept: a camera hands its links what it sent before the crash, and nothing else.
caf::error crash_reason();

/// How the fault injector takes part in the clock: phase faults; every tick when random node
/// failures are on or the run is live (`live`: it takes the operator's commands), else woken at
/// its next scheduled fault.
participant_info fault_injector_participant(const config::scenario& scenario, bool live = false);

/// Spawns the fault injector (docs/network.md). At each scheduled fault's time, and at random
/// with `network.node_failure_probability` per node per second of virtual time, it:
/// - `crash`: retires the camera at the clock, kills its actor (a CAF exit, `crash_reason()`),
///   and tells the camera's links that the node is down, so messages to it are dropped. Its
///   acknowledgement waits for the camera's end: what the camera had already sent is handed to
///   its links as it goes (actors/link_outbox.hpp);
/// - `crash_and_recover`: the same, then after `length` spawns a fresh, empty-handed camera
///   actor, joins it to the clock and attaches it to its links (`node_recovered`);
/// - `link_cut` / `link_heal`: cuts or heals the link between `camera` and `peer`;
/// - `loss_burst`: sets every link of `camera` to `loss_probability` for `length`;
/// - `delay_spike`: every message sent on a link of `camera` for `length` takes `delay` longer;
/// - `recover`: the second half of a crash_and_recover on its own (`node_recovered`).
/// - a `lost_worker` from the clock (`--on-worker-loss crash-nodes`): at the start of its next
///   turn, each of the worker's cameras is down as a crashed one is (fault `worker_lost`), and
///   never recovers.
/// Every action is logged as a `fault` event. Commands to links are requests, sent in the
/// order they were made once the turn's crashed cameras have ended, and the injector's
/// acknowledgement waits for every answer: a link's effects on the nodes (hand-overs,
/// retractions) are then in their mailboxes before their turn. Camera nodes are told nothing:
/// they learn of failures only through silence (node_network).
///
/// In a live run (`live` given) it takes the operator's crash, recover, cut and heal commands
/// from `live->queue` at the start of each turn: each becomes a fault of the scenario at this
/// tick (as `live::apply_commands` makes it for a replay), carried out after the scheduled
/// faults of the tick and before the random ones — where a replay carries it out — and
/// recorded in `live->log`.
caf::actor spawn_fault_injector(caf::actor_system& system, const config::scenario& scenario,
                                caf::actor clock, network_directory directory,
                                std::shared_ptr<live::session> live = nullptr);

}  // namespace argus::actors
