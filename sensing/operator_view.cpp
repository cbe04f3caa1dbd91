#include "sensing/operator_view.hpp"

#include "vision/emulated_sensor.hpp"

namespace argus::sensing {

std::optional<cv::Rect2d> operator_box(const world::snapshot& frame, const world::station& where,
                                       const vision::camera_view& view, int id,
                                       double max_occlusion) {
  for (const auto& seen : vision::visible_pedestrians(frame, where, view))
    if (seen.id == id && seen.occlusion <= max_occlusion) return operator_box(seen, view);
  return std::nullopt;
}

std::optional<cv::Rect2d> operator_box(const vision::pedestrian_view& seen,
                                       const vision::camera_view& view, double max_occlusion) {
  if (seen.occlusion > max_occlusion) return std::nullopt;
  const auto box = seen.box & cv::Rect2d(0.0, 0.0, view.width_px, view.height_px);
  if (box.area() <= 0.0) return std::nullopt;
  return box;
}

}  // namespace argus::sensing
