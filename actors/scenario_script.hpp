#pragma once

#include "actors/operator_board.hpp"
#include "actors/participant_info.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"
#include "eval/observation_log.hpp"
#include "live/session.hpp"

namespace argus::actors {

/// How the scenario script takes part in the clock: phase faults, woken at its next task, or
/// every tick in a live run (`live`), to take the operator's commands.
participant_info script_participant(bool live = false);

/// Spawns the scenario script: at each operator task's time it logs `task_issued` (the
/// operator's request; the task's camera node acts on it in the same tick), and at its
/// `cancel_at` logs `task_cancelled` and tells `log` (the evaluation's record, may be null).
/// Faults are the fault injector's (fault_injector.hpp). The caller joins the script with
/// `script_participant()` before the clock starts.
///
/// In a live run (`live` and `operators` given) it also takes the operator's task and cancel
/// commands from `live->queue` at the start of each turn: that turn's tick is when they take
/// effect. A task becomes the scenario's next task (by pixel, at this tick), a cancellation its
/// task's `cancel_at`; both are then carried out exactly as scenario entries at this tick would
/// be — the same events, in the same order (by tick, task, issue before cancel) — published on
/// `operators` for the task's camera node and recorded in `live->log`. A cancellation of a
/// task not yet issued, or already cancelled, is refused (told to the console, not logged).
caf::actor spawn_scenario_script(caf::actor_system& system, const config::scenario& scenario,
                                 caf::actor clock,
                                 std::shared_ptr<eval::observation_log> log = nullptr,
                                 std::shared_ptr<live::session> live = nullptr,
                                 std::shared_ptr<operator_board> operators = nullptr);

}  // namespace argus::actors
