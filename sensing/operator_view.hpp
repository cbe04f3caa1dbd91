#pragma once

#include <optional>

#include "opencv2/core/types.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::world {
class snapshot;
class station;
}  // namespace argus::world

namespace argus::vision {
struct pedestrian_view;
}  // namespace argus::vision

namespace argus::sensing {

/// Where the operator sees pedestrian `id` in a camera's frame: the box of its visible part
/// (clipped to the frame), or nullopt when it is not in view (absent, behind a wall, or hidden
/// beyond `max_occlusion`). Simulator knowledge standing for the operator's click; it reaches
/// the node only as that box.
std::optional<cv::Rect2d> operator_box(const world::snapshot& frame, const world::station& where,
                                       const vision::camera_view& view, int id,
                                       double max_occlusion = 0.9);

/// operator_box() of a pedestrian already found visible (`seen`, of vision::visible_pedestrians
/// through `view`): for callers that weigh everyone in view with one visibility pass.
std::optional<cv::Rect2d> operator_box(const vision::pedestrian_view& seen,
                                       const vision::camera_view& view, double max_occlusion = 0.9);

}  // namespace argus::sensing
