#pragma once

// The relevance of a camera to a task, eq. (1) (Section III-D).

#include "config/scenario.hpp"
#include "vision/ptz_pose.hpp"

namespace argus::vision {

/// Whether a camera is free or already busy with another task.
enum class camera_availability { free, busy };

/// eq. (1):
///   r = exp(-(θ - θ̂)² / 2σθ² - (α - α̂)² / 2σα² - (β - β̂)² / 2σβ²)   if the camera is free,
///   r = 0                                                           if it is busy,
/// where θ, α, β are the field of view, pan and tilt the camera needs to centre the target
/// (`required`, e.g. from centring_pose()), θ̂, α̂, β̂ the mid-points of the camera's field of
/// view, pan and tilt limits, and σ the spreads of `controller` (5.0 degrees by default, as
/// in the paper). A camera with more leeway to turn and zoom is more relevant.
double relevance(const ptz_pose& required, const config::camera_settings& camera,
                 const config::controller_settings& controller, camera_availability availability);

}  // namespace argus::vision
