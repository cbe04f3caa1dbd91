#pragma once

#include <map>

#include "actors/participant_info.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"

namespace argus::actors {

/// How the scenario script takes part in the clock: phase faults, woken at its next action.
participant_info script_participant();

/// Spawns the scenario script: at each operator task's and fault's time it logs the action
/// (`task_issued`, `fault`) and carries out what the runtime supports today:
/// - `crash`: retires the camera at the clock, then kills its actor (deterministically: the
///   retire reaches the clock before the script's own ack);
/// - `crash_and_recover`: the same, and after `length` a fresh, empty-handed camera actor is
///   spawned and joined (`node_recovered`);
/// - `link_cut`, `link_heal`, `loss_burst`: logged with `"applied":false` until the link layer
///   (network issue) exists.
/// `cameras` maps scenario camera ids to their actors; the caller joins the script itself
/// with `script_participant()` before the clock starts.
caf::actor spawn_scenario_script(caf::actor_system& system, const config::scenario& scenario,
                                 caf::actor clock, std::map<int, caf::actor> cameras);

}  // namespace argus::actors
