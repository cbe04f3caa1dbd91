#include "vision/fixate_zoom.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace argus::vision {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

// A simulated pan-tilt pinhole camera (same conventions as ptz_pose.hpp) looking at a
// pedestrian-sized target (0.6 m x 1.8 m) at a world position:
//
//        z (up)
//        |   target
//        |  /
//   camera -------> x (pan 0)
struct simulated_camera {
  frame_size frame{320, 240};
  // The target's box in the image for a pose, from the target's centre position.
  cv::Rect2d project(const ptz_pose& pose, const double target[3]) const {
    const double p = pose.pan_deg * deg, t = pose.tilt_deg * deg;
    const double fwd[3] = {std::cos(t) * std::cos(p), std::cos(t) * std::sin(p), std::sin(t)};
    const double right[3] = {std::sin(p), -std::cos(p), 0.0};
    const double up[3] = {-std::sin(t) * std::cos(p), -std::sin(t) * std::sin(p), std::cos(t)};
    double x = 0, y = 0, z = 0;
    for (int i = 0; i < 3; ++i) {
      x += target[i] * right[i];
      y += target[i] * up[i];
      z += target[i] * fwd[i];
    }
    const double f = focal_length_px(pose.field_of_view_deg, frame.width_px);
    const double u = frame.width_px / 2.0 + f * x / z;
    const double v = frame.height_px / 2.0 - f * y / z;
    const double h = f * 1.8 / z, w = f * 0.6 / z;
    return {u - w / 2, v - h / 2, w, h};
  }
};

double centre_error_px(const cv::Rect2d& box, const frame_size& frame) {
  return std::hypot(box.x + box.width / 2 - frame.width_px / 2.0,
                    box.y + box.height / 2 - frame.height_px / 2.0);
}

TEST(fixate_zoom, centring_pose_centres_the_box) {
  simulated_camera camera;
  const double target[3] = {20.0, 6.0, -5.0};
  ptz_pose pose{10.0, -5.0, 40.0};
  auto box = camera.project(pose, target);
  auto goal = centring_pose(pose, box, camera.frame, 0.5);
  auto centred = camera.project(goal, target);
  EXPECT_LT(centre_error_px(centred, camera.frame), 1e-6);
  // Zoom scales the box from its off-axis size: within a few percent once centred.
  EXPECT_NEAR(centred.height, 0.5 * camera.frame.height_px, 0.03 * camera.frame.height_px);
  // The target is left of the camera's pan and below: pan grows, tilt falls.
  EXPECT_GT(goal.pan_deg, 0.0);
  EXPECT_LT(goal.tilt_deg, 0.0);
}

TEST(fixate_zoom, converges_without_overshoot) {
  simulated_camera camera;
  config::camera_settings settings;  // limits and slew rates
  const double target[3] = {20.0, -8.0, -6.0};
  ptz_pose pose{25.0, 0.0, 60.0};
  auto box = camera.project(pose, target);
  double first_error = centre_error_px(box, camera.frame);
  double previous = first_error;
  double initial_sign = (box.x + box.width / 2) - camera.frame.width_px / 2.0;
  double overshoot = 0.0;
  for (int frame = 0; frame < 150; ++frame) {  // 10 s at 15 frames/s
    pose = fixate_zoom_step(pose, box, camera.frame, settings, config::seconds{1.0 / 15.0});
    box = camera.project(pose, target);
    double error = centre_error_px(box, camera.frame);
    EXPECT_LE(error, previous + 1.0) << "frame " << frame;
    previous = error;
    double dx = (box.x + box.width / 2) - camera.frame.width_px / 2.0;
    if (dx * initial_sign < 0) overshoot = std::max(overshoot, std::abs(dx));
  }
  EXPECT_GT(first_error, 50.0);
  EXPECT_LT(previous, 2.0);
  EXPECT_LT(overshoot, 2.0);  // pixels past the centre
  EXPECT_NEAR(box.height / camera.frame.height_px, 0.5, 0.02);
}

TEST(fixate_zoom, respects_limits_and_slew_rates) {
  config::camera_settings settings;
  settings.pan_limits = {-10.0, 10.0};
  settings.field_of_view_limits = {20.0, 50.0};
  ptz_pose pose{9.0, 0.0, 30.0};
  // A tiny box far right: wants lots of pan to the right (negative) and a narrow FOV.
  cv::Rect2d box(300, 110, 4, 12);
  auto next = fixate_zoom_step(pose, box, {320, 240}, settings, config::seconds{1.0 / 15.0});
  EXPECT_GE(next.pan_deg, pose.pan_deg - settings.pan_rate_deg_per_s / 15.0 - 1e-9);
  EXPECT_LT(next.pan_deg, pose.pan_deg);
  EXPECT_GE(next.field_of_view_deg, 20.0);
  auto wide = slew_towards(pose, {100.0, 0.0, 90.0}, settings, config::seconds{10.0});
  EXPECT_EQ(wide.pan_deg, 10.0);
  EXPECT_EQ(wide.field_of_view_deg, 50.0);
}

}  // namespace
}  // namespace argus::vision
