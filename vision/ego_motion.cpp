#include "vision/ego_motion.hpp"

#include <cmath>
#include <numbers>

#include "vision/fixate_zoom.hpp"

namespace argus::vision {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

// A camera's axes in the base frame (z up, pan 0 along x), as in centring_pose().
struct axes {
  double forward[3];
  double right[3];
  double up[3];
};

axes axes_of(const ptz_state& pose) {
  const double p = pose.pan_deg * deg, t = pose.tilt_deg * deg;
  return {{std::cos(t) * std::cos(p), std::cos(t) * std::sin(p), std::sin(t)},
          {std::sin(p), -std::cos(p), 0.0},
          {-std::sin(t) * std::cos(p), -std::sin(t) * std::sin(p), std::cos(t)}};
}

double dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace

std::optional<cv::Rect2d> reproject_box(const cv::Rect2d& box, const ptz_state& from,
                                        const ptz_state& to, const frame_size& frame) {
  const double f_from = focal_length_px(from.field_of_view_deg, frame.width_px);
  const double f_to = focal_length_px(to.field_of_view_deg, frame.width_px);
  const double cx = box.x + box.width / 2.0 - frame.width_px / 2.0;
  const double cy = frame.height_px / 2.0 - (box.y + box.height / 2.0);
  const auto a = axes_of(from);
  double ray[3];
  for (int i = 0; i < 3; ++i) ray[i] = cx * a.right[i] + cy * a.up[i] + f_from * a.forward[i];
  const auto b = axes_of(to);
  const double z = dot(ray, b.forward);
  if (!(z > 0.0)) return std::nullopt;
  const double x = f_to * dot(ray, b.right) / z;
  const double y = f_to * dot(ray, b.up) / z;
  const double scale = f_to / f_from;
  const double w = box.width * scale, h = box.height * scale;
  return cv::Rect2d(frame.width_px / 2.0 + x - w / 2.0, frame.height_px / 2.0 - y - h / 2.0, w, h);
}

}  // namespace argus::vision
