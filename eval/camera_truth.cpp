#include "eval/camera_truth.hpp"

#include <algorithm>

namespace argus::eval {

vision::camera_view camera_truth::view(const vision::ptz_state& pose) const {
  vision::camera_view v;
  v.placement = vision::camera_placement::from(camera);
  v.pose = pose;
  v.width_px = static_cast<int>(camera.imaging.width_px);
  v.height_px = static_cast<int>(camera.imaging.height_px);
  return v;
}

std::optional<int> camera_truth::target_of(controller::task_id task) const {
  return log ? log->target_of(task) : std::nullopt;
}

std::optional<controller::task_id> looked_for_unheld(const controller::strategy_status& s,
                                                     const controller::controller_output& out,
                                                     bool found_now) {
  switch (s.state) {
    case controller::node_state::performing_task:
      if (s.tracking == vision::tracking_state::track) return std::nullopt;
      return s.task;
    case controller::node_state::computing_relevance:
      if (found_now || out.looks.empty()) return std::nullopt;
      return out.looks.front().task;
    case controller::node_state::idle:
      break;
  }
  return std::nullopt;
}

bool found_any(const controller::controller_input& in) {
  return std::any_of(in.looks.begin(), in.looks.end(), [](const auto& l) { return l.found; });
}

}  // namespace argus::eval
