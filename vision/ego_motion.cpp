#include "vision/ego_motion.hpp"

#include "vision/fixate_zoom.hpp"

namespace argus::vision {

std::optional<cv::Rect2d> reproject_box(const cv::Rect2d& box, const ptz_state& from,
                                        const ptz_state& to, const frame_size& frame) {
  const auto ray = ray_through({box.x + box.width / 2.0, box.y + box.height / 2.0}, from, frame);
  const auto b = axes_of(to);
  const double z = ray.dot(b.forward);
  if (!(z > 0.0)) return std::nullopt;
  const double f_to = focal_length_px(to.field_of_view_deg, frame.width_px);
  const double x = f_to * ray.dot(b.right) / z;
  const double y = f_to * ray.dot(b.up) / z;
  const double scale = f_to / focal_length_px(from.field_of_view_deg, frame.width_px);
  const double w = box.width * scale, h = box.height * scale;
  return cv::Rect2d(frame.width_px / 2.0 + x - w / 2.0, frame.height_px / 2.0 - y - h / 2.0, w, h);
}

}  // namespace argus::vision
