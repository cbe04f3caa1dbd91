#include "vision/fixate_zoom.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace argus::vision {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

// Wraps an angle difference into (-180, 180].
double wrapped(double d) {
  return std::remainder(d, 360.0);
}

}  // namespace

double focal_length_px(double field_of_view_deg, int frame_width_px) {
  return 0.5 * frame_width_px / std::tan(0.5 * field_of_view_deg * deg);
}

camera_axes axes_of(const ptz_state& pose) {
  const double p = pose.pan_deg * deg, t = pose.tilt_deg * deg;
  return {{std::cos(t) * std::cos(p), std::cos(t) * std::sin(p), std::sin(t)},
          {std::sin(p), -std::cos(p), 0.0},
          {-std::sin(t) * std::cos(p), -std::sin(t) * std::sin(p), std::cos(t)}};
}

cv::Vec3d ray_through(const cv::Point2d& pixel, const ptz_state& pose, const frame_size& frame) {
  const double f = focal_length_px(pose.field_of_view_deg, frame.width_px);
  // The pixel in camera axes: x right, y up, z forward.
  const double cx = pixel.x - frame.width_px / 2.0;
  const double cy = frame.height_px / 2.0 - pixel.y;
  const auto a = axes_of(pose);
  cv::Vec3d w;
  for (int i = 0; i < 3; ++i) w[i] = cx * a.right[i] + cy * a.up[i] + f * a.forward[i];
  return w;
}

ptz_state centring_pose(const ptz_state& current, const cv::Rect2d& box, const frame_size& frame,
                        double height_fraction) {
  const double f = focal_length_px(current.field_of_view_deg, frame.width_px);
  const auto w = ray_through({box.x + box.width / 2.0, box.y + box.height / 2.0}, current, frame);
  ptz_state goal;
  goal.pan_deg = std::atan2(w[1], w[0]) / deg;
  goal.tilt_deg = std::atan2(w[2], std::hypot(w[0], w[1])) / deg;
  // Zoom: the focal length that makes the box height_fraction of the frame height.
  const double wanted_f = f * height_fraction * frame.height_px / std::max(box.height, 1.0);
  goal.field_of_view_deg = 2.0 * std::atan(0.5 * frame.width_px / wanted_f) / deg;
  // Keep pan continuous with the current one (no jump across +-180).
  goal.pan_deg = current.pan_deg + wrapped(goal.pan_deg - current.pan_deg);
  return goal;
}

ptz_state fixate_zoom_step(const ptz_state& current, const cv::Rect2d& box, const frame_size& frame,
                           const ptz_limits& limits, config::seconds dt,
                           const fixate_zoom_settings& settings) {
  const auto goal = centring_pose(current, box, frame, settings.height_fraction);
  ptz_state wanted = current;
  auto move = [&](double from, double to, double gain) {
    return std::abs(to - from) < settings.dead_band_deg ? from : from + gain * (to - from);
  };
  wanted.pan_deg = move(current.pan_deg, goal.pan_deg, settings.fixate_gain);
  wanted.tilt_deg = move(current.tilt_deg, goal.tilt_deg, settings.fixate_gain);
  wanted.field_of_view_deg =
      current.field_of_view_deg +
      settings.zoom_gain * (goal.field_of_view_deg - current.field_of_view_deg);
  return slew_towards(current, wanted, limits, dt);
}

}  // namespace argus::vision
