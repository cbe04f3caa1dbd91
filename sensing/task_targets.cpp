#include "sensing/task_targets.hpp"

#include "vision/emulated_sensor.hpp"

namespace argus::sensing {
namespace {

// As operator_box: hidden beyond this, nobody could click on her.
constexpr double max_occlusion = 0.9;

}  // namespace

int pedestrian_at(const world::snapshot& frame, const world::station& where,
                  const vision::camera_view& view, const cv::Point2d& pixel) {
  const cv::Rect2d image(0.0, 0.0, view.width_px, view.height_px);
  // Nearest first: the first box that holds the click is the one in front.
  for (const auto& seen : vision::visible_pedestrians(frame, where, view)) {
    if (seen.occlusion > max_occlusion) continue;
    if ((seen.box & image).contains(pixel)) return seen.id;
  }
  return 0;
}

std::set<int> in_view(const world::snapshot& frame, const world::station& where,
                      const vision::camera_view& view) {
  const cv::Rect2d image(0.0, 0.0, view.width_px, view.height_px);
  std::set<int> out;
  for (const auto& seen : vision::visible_pedestrians(frame, where, view))
    if (seen.occlusion <= max_occlusion && (seen.box & image).area() > 0.0) out.insert(seen.id);
  return out;
}

int entry_watch::step(const std::set<int>& in_view_now) {
  if (!primed_) {
    prime(in_view_now);
    return 0;
  }
  int entered = 0;
  for (int id : in_view_now)
    if (before_.count(id) == 0) {
      entered = id;
      break;
    }
  before_ = in_view_now;
  return entered;
}

}  // namespace argus::sensing
