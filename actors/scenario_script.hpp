#pragma once

#include "actors/participant_info.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"

namespace argus::actors {

/// How the scenario script takes part in the clock: phase faults, woken at its next task.
participant_info script_participant();

/// Spawns the scenario script: at each operator task's time it logs `task_issued` (the
/// operator's request; camera nodes act on it once the controller exists). Faults are the
/// fault injector's (fault_injector.hpp). The caller joins the script with
/// `script_participant()` before the clock starts.
caf::actor spawn_scenario_script(caf::actor_system& system, const config::scenario& scenario,
                                 caf::actor clock);

}  // namespace argus::actors
