#pragma once

#include "actors/participant_info.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"
#include "eval/observation_log.hpp"

namespace argus::actors {

/// How the scenario script takes part in the clock: phase faults, woken at its next task.
participant_info script_participant();

/// Spawns the scenario script: at each operator task's time it logs `task_issued` (the
/// operator's request; the task's camera node acts on it in the same tick), and at its
/// `cancel_at` logs `task_cancelled` and tells `log` (the evaluation's record, may be null).
/// Faults are the fault injector's (fault_injector.hpp). The caller joins the script with
/// `script_participant()` before the clock starts.
caf::actor spawn_scenario_script(caf::actor_system& system, const config::scenario& scenario,
                                 caf::actor clock,
                                 std::shared_ptr<eval::observation_log> log = nullptr);

}  // namespace argus::actors
