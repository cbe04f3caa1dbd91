#pragma once

#include "actors/participant_info.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"

namespace argus::actors {

/// How camera `camera` takes part in the clock: phase cameras, every tick (it senses each frame).
participant_info camera_participant(const config::camera_settings& camera);

/// Spawns the actor of one camera node; the caller joins it to the clock with
/// `camera_participant(camera)`, before the clock starts or from inside a tick, so that joins
/// stay deterministic.
///
/// Today the node is the shell that later issues fill: it announces itself (`node_up`) on its
/// first tick and acknowledges every tick; sensing (vision/), the controller FSM of Fig. 10
/// and the grouping protocol (protocol/) are not in it yet.
caf::actor spawn_camera_node(caf::actor_system& system, const config::camera_settings& camera);

}  // namespace argus::actors
