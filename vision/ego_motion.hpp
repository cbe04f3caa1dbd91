#pragma once

// Where a box seen at one pan/tilt/zoom appears at another: the camera's own motion between
// two frames, from its own angles and field of view only (the pinhole model of
// fixate_zoom.hpp; no calibration, no world positions). A tracker on an active camera needs
// it: fixating a target at the frame's edge moves her a third of the frame in a few frames,
// far beyond any search window around her last box, and zooming in grows her box faster
// than any per-frame size range allows.

#include <optional>

#include "opencv2/core.hpp"
#include "vision/frame_size.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::vision {

/// The box that `box`, seen at pose `from`, covers at pose `to`: its centre's ray projected
/// again, its size scaled by the ratio of the focal lengths. Empty when the ray is behind the
/// camera at `to`.
std::optional<cv::Rect2d> reproject_box(const cv::Rect2d& box, const ptz_state& from,
                                        const ptz_state& to, const frame_size& frame);

}  // namespace argus::vision
