#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <vector>

#include "config/scenario.hpp"
#include "vision/ptz_camera.hpp"
#include "world/layout.hpp"

namespace argus::world {
class snapshot;
class station;
}  // namespace argus::world

namespace argus::eval {

/// A task as the oracle strategy sees it: whom to observe, with how many cameras.
struct oracle_target {
  std::uint32_t task = 0;
  int pedestrian = 0;
  unsigned cameras = 1;
};

/// The central oracle's camera assignment (controller.strategy: oracle): an upper bound
/// that knows where everyone is and needs no messages. Tasks in id order take, each, the
/// `cameras` nearest live cameras that can reach their target (eval::reachable) and are not
/// taken yet; a camera keeps its task unless another is more than a quarter nearer, so that
/// cameras do not flap between equals. Returns camera id -> task.
std::map<int, std::uint32_t> assign_cameras(const std::vector<config::camera_settings>& cameras,
                                            const std::set<int>& alive,
                                            const world::snapshot& frame,
                                            const world::station& station,
                                            const std::vector<oracle_target>& targets,
                                            const std::map<int, std::uint32_t>& previous);

/// The pose that centres a body `height_m` tall standing at `where` in `camera`'s view, a third
/// of the frame's height with `zoom`, else at the camera's default field of view; within the
/// head's limits.
vision::ptz_state pose_towards(const config::camera_settings& camera, const world::vec2& where,
                               double height_m, bool zoom = true);

/// The pose that centres pedestrian `pedestrian` of `frame` in `camera`'s view with her body
/// a third of the frame's height, within the head's limits; the home pose when she is gone.
/// With `zoom` false, the pose centres her with the camera's default field of view.
vision::ptz_state oracle_pose(const config::camera_settings& camera, const world::snapshot& frame,
                              int pedestrian, bool zoom = true);

}  // namespace argus::eval
