#pragma once

#include "actors/fault_injector.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"

namespace argus::actors {

/// Spawns the scenario's network — one link actor per pair of neighbours
/// (`protocol::topology`), one camera node per camera — attaches every node to its links and
/// joins them all to `clock`. Everything goes out from the calling thread in this order, so it
/// reaches its receivers before the clock's first tick. Returns what the fault injector acts on.
network_directory spawn_network(caf::actor_system& system, const config::scenario& scenario,
                                const caf::actor& clock);

}  // namespace argus::actors
