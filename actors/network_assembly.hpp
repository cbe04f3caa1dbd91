#pragma once

#include <utility>
#include <vector>

#include "actors/fault_injector.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"
#include "protocol/topology.hpp"

namespace argus::actors {

/// Spawns the scenario's network — one link actor per link of `topo` (the scenario's
/// `protocol::topology`), one camera node per camera — attaches every node to its links and
/// joins them all to `clock`. Everything goes out from the calling thread in this order, so it
/// reaches its receivers before the clock's first tick. Returns what the fault injector acts on.
/// `world` is what the cameras sense with (null: cameras without a sensor).
network_directory spawn_network(caf::actor_system& system, const config::scenario& scenario,
                                const protocol::topology& topo, const caf::actor& clock,
                                std::shared_ptr<const camera_world> world = nullptr);

/// The end of spawn_network, for wherever its cameras and links were spawned: attaches every
/// camera of `net` to each of its links (in camera, then neighbour order, stamped before tick 0)
/// and joins `links` to `clock`.
void attach_and_join_links(const network_directory& net,
                           const std::vector<std::pair<caf::actor, participant_info>>& links,
                           const caf::actor& clock);

}  // namespace argus::actors
