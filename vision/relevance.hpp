#pragma once

// The relevance of a camera to a task, eq. (1) (Section III-D).

#include "config/scenario.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::vision {

/// Whether a camera is free or already busy with another task.
enum class camera_availability { free, busy };

/// eq. (1):
///   r = exp(-(θ - θ̂)² / 2σθ² - (α - α̂)² / 2σα² - (β - β̂)² / 2σβ²)   if the camera is free,
///   r = 0                                                           if it is busy,
/// where θ, α, β are the field of view, pan and tilt the camera needs to centre the target
/// (`required`, e.g. from centring_pose()), θ̂, α̂, β̂ the mid-points of the camera's field of
/// view, pan and tilt `limits` (ptz_limits::from() of the camera), and σ the spreads of
/// `controller` (5.0 degrees by default, as in the paper). A camera with more leeway to turn
/// and zoom is more relevant. When pan turns all the way round (ptz_limits::pan_wraps), the pan
/// term is 0: such a head never runs out of pan, and α̂ = 0 of [-180, 180] would only measure a
/// compass direction (docs/protocol.md).
///
/// A static camera's limits collapse onto its fixed pose, so its hat values are that pose: its
/// relevance is 1 for a target already centred at the wanted zoom in its fixed view, and
/// falls off as eq. (1)'s Gaussian with how far it would have to turn and zoom — the same
/// scale on which the PTZ cameras it competes with are judged.
double relevance(const ptz_state& required, const ptz_limits& limits,
                 const config::controller_settings& controller, camera_availability availability);

}  // namespace argus::vision
