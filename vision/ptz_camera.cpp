#include "vision/ptz_camera.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace argus::vision {
namespace {

constexpr double deg = M_PI / 180.0;

// Angle in (-180, 180].
double wrap_deg(double a) {
  a = std::fmod(a, 360.0);
  if (a <= -180.0) a += 360.0;
  if (a > 180.0) a -= 360.0;
  return a;
}

double clamp_range(double v, const config::degree_range& r) {
  return std::clamp(v, r.min_deg, r.max_deg);
}

// At most `max_step` from `from` toward `to`; exactly `to` once within reach.
double approach(double from, double to, double max_step) {
  const double delta = to - from;
  if (std::abs(delta) <= max_step) return to;
  return from + std::clamp(delta, -max_step, max_step);
}

}  // namespace

ptz_state ptz_limits::clamp(const ptz_state& wanted) const noexcept {
  ptz_state out;
  out.pan_deg = pan_wraps() ? wrap_deg(wanted.pan_deg) : clamp_range(wanted.pan_deg, pan);
  out.tilt_deg = clamp_range(wanted.tilt_deg, tilt);
  out.field_of_view_deg = clamp_range(wanted.field_of_view_deg, field_of_view);
  return out;
}

ptz_limits ptz_limits::from(const config::camera_settings& camera) {
  ptz_limits limits;
  if (camera.type == config::camera_type::static_camera) {
    // A static camera is a PTZ camera that cannot move: ranges shrink to its pose.
    limits.pan = {camera.pan_deg, camera.pan_deg};
    limits.tilt = {camera.tilt_deg, camera.tilt_deg};
    limits.field_of_view = {camera.field_of_view_deg, camera.field_of_view_deg};
    limits.pan_rate_deg_per_s = limits.tilt_rate_deg_per_s = limits.zoom_rate_deg_per_s = 0.0;
    return limits;
  }
  limits.pan = camera.pan_limits;
  limits.tilt = camera.tilt_limits;
  limits.field_of_view = camera.field_of_view_limits;
  limits.pan_rate_deg_per_s = camera.pan_rate_deg_per_s;
  limits.tilt_rate_deg_per_s = camera.tilt_rate_deg_per_s;
  limits.zoom_rate_deg_per_s = camera.zoom_rate_deg_per_s;
  return limits;
}

ptz_state slew_towards(const ptz_state& current, const ptz_state& goal, const ptz_limits& limits,
                       config::seconds dt) {
  const double s = std::max(0.0, dt.count());
  const ptz_state to = limits.clamp(goal);
  ptz_state next;
  if (limits.pan_wraps()) {
    // Shorter way round; the result is wrapped back into (-180, 180].
    const double delta = wrap_deg(to.pan_deg - current.pan_deg);
    const double max_step = limits.pan_rate_deg_per_s * s;
    next.pan_deg = std::abs(delta) <= max_step
                       ? to.pan_deg
                       : current.pan_deg + std::clamp(delta, -max_step, max_step);
  } else {
    next.pan_deg = approach(current.pan_deg, to.pan_deg, limits.pan_rate_deg_per_s * s);
  }
  next.tilt_deg = approach(current.tilt_deg, to.tilt_deg, limits.tilt_rate_deg_per_s * s);
  next.field_of_view_deg =
      approach(current.field_of_view_deg, to.field_of_view_deg, limits.zoom_rate_deg_per_s * s);
  // Within the limits whatever `current` was: a static camera stays on its pose.
  return limits.clamp(next);
}

camera_placement camera_placement::from(const config::camera_settings& camera) {
  return {Eigen::Vector3d{camera.position.x_m, camera.position.y_m, camera.height_m}};
}

double camera_view::focal_px() const noexcept {
  return 0.5 * width_px / std::tan(0.5 * pose.field_of_view_deg * deg);
}

Eigen::Matrix3d camera_view::orientation() const noexcept {
  const double pan = pose.pan_deg * deg;
  const double tilt = pose.tilt_deg * deg;
  const Eigen::Vector3d forward{std::cos(tilt) * std::cos(pan), std::cos(tilt) * std::sin(pan),
                                std::sin(tilt)};
  const Eigen::Vector3d right{std::sin(pan), -std::cos(pan), 0.0};
  Eigen::Matrix3d r;
  r.col(0) = right;
  r.col(1) = right.cross(forward);
  r.col(2) = forward;
  return r;
}

std::optional<Eigen::Vector2d> camera_view::project(const Eigen::Vector3d& p) const {
  return camera_projection(*this).project(p);
}

camera_projection::camera_projection(const camera_view& view)
    : orientation_(view.orientation()),
      position_m_(view.placement.position_m),
      focal_px_(view.focal_px()),
      width_px_(view.width_px),
      height_px_(view.height_px) {
  // nop
}

std::optional<Eigen::Vector2d> camera_projection::project(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d c = orientation_.transpose() * (p - position_m_);
  if (c.z() <= 1e-9) return std::nullopt;
  const double f = focal_px_;
  // Window coordinates put pixel centres at +0.5; OpenCV puts them at integers.
  return Eigen::Vector2d{0.5 * width_px_ + f * c.x() / c.z() - 0.5,
                         0.5 * height_px_ - f * c.y() / c.z() - 0.5};
}

Eigen::Vector3d camera_view::back_project(const Eigen::Vector2d& pixel) const {
  const double f = focal_px();
  const Eigen::Vector3d c{(pixel.x() + 0.5 - 0.5 * width_px) / f,
                          (0.5 * height_px - pixel.y() - 0.5) / f, 1.0};
  return (orientation() * c).normalized();
}

std::optional<Eigen::Vector3d> camera_view::floor_point(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector3d ray = back_project(pixel);
  if (ray.z() >= -1e-9) return std::nullopt;
  const double t = -placement.position_m.z() / ray.z();
  return placement.position_m + t * ray;
}

Eigen::Matrix4f camera_view::gl_view() const noexcept {
  const Eigen::Matrix3d r = orientation();
  Eigen::Matrix4d v = Eigen::Matrix4d::Identity();
  // Eye axes: x = right, y = up, z = -forward.
  v.block<1, 3>(0, 0) = r.col(0).transpose();
  v.block<1, 3>(1, 0) = r.col(1).transpose();
  v.block<1, 3>(2, 0) = -r.col(2).transpose();
  v.block<3, 1>(0, 3) = -v.block<3, 3>(0, 0) * placement.position_m;
  return v.cast<float>();
}

Eigen::Matrix4f camera_view::gl_projection(double near_m, double far_m,
                                           bool flip_y) const noexcept {
  const double f = focal_px();
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = 2.0 * f / width_px;
  p(1, 1) = (flip_y ? -2.0 : 2.0) * f / height_px;
  p(2, 2) = -(far_m + near_m) / (far_m - near_m);
  p(2, 3) = -2.0 * far_m * near_m / (far_m - near_m);
  p(3, 2) = -1.0;
  return p.cast<float>();
}

ptz_camera::ptz_camera(ptz_limits limits, ptz_state initial)
    : limits_(limits), state_(limits.clamp(initial)), target_(state_) {}

ptz_camera ptz_camera::from(const config::camera_settings& camera) {
  return ptz_camera(ptz_limits::from(camera),
                    {camera.pan_deg, camera.tilt_deg, camera.field_of_view_deg});
}

void ptz_camera::command(const ptz_state& wanted) {
  target_ = limits_.clamp(wanted);
}

void ptz_camera::step(config::seconds dt) {
  state_ = slew_towards(state_, target_, limits_, dt);
}

}  // namespace argus::vision
