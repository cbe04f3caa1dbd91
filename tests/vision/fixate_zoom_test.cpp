#include "vision/fixate_zoom.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/vision/static_camera.hpp"

namespace argus::vision {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

// A simulated pan-tilt pinhole camera (same conventions as ptz_camera.hpp) looking at a
// pedestrian-sized target (0.6 m x 1.8 m) at a world position:
//
//        z (up)
//        |   target
//        |  /
//   camera -------> x (pan 0)
struct simulated_camera {
  frame_size frame{320, 240};
  // The target's box in the image for a pose, from the target's centre position.
  cv::Rect2d project(const ptz_state& pose, const double target[3]) const {
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
  ptz_state pose{10.0, -5.0, 40.0};
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
  const ptz_limits settings;  // limits and slew rates
  const double target[3] = {20.0, -8.0, -6.0};
  ptz_state pose{25.0, 0.0, 60.0};
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
  ptz_limits settings;
  settings.pan = {-10.0, 10.0};
  settings.field_of_view = {20.0, 50.0};
  ptz_state pose{9.0, 0.0, 30.0};
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

TEST(fixate_zoom, slew_towards_pans_the_shorter_way_round) {
  const ptz_limits limits;  // pan [-180, 180] wraps; 60 deg/s
  // From 170 to -170 is 20 degrees through 180, not 340 through 0.
  auto next =
      slew_towards({170.0, -20.0, 45.0}, {-170.0, -20.0, 45.0}, limits, config::seconds{0.1});
  EXPECT_NEAR(next.pan_deg, 176.0, 1e-9);
  next = slew_towards(next, {-170.0, -20.0, 45.0}, limits, config::seconds{0.1});
  EXPECT_NEAR(next.pan_deg, -178.0, 1e-9);  // across 180, wrapped into (-180, 180]
  next = slew_towards(next, {-170.0, -20.0, 45.0}, limits, config::seconds{1.0});
  EXPECT_EQ(next.pan_deg, -170.0);
  // A goal kept continuous past 180 (as centring_pose does) is the same pose.
  EXPECT_EQ(slew_towards({170.0, -20.0, 45.0}, {190.0, -20.0, 45.0}, limits, config::seconds{1.0})
                .pan_deg,
            -170.0);
  // Without wrap (limits narrower than a turn), pan goes the long way within its limits.
  ptz_limits narrow;
  narrow.pan = {-175.0, 175.0};
  EXPECT_NEAR(
      slew_towards({170.0, -20.0, 45.0}, {-170.0, -20.0, 45.0}, narrow, config::seconds{0.1})
          .pan_deg,
      164.0, 1e-9);
}

TEST(fixate_zoom, a_static_camera_never_moves) {
  const auto limits = ptz_limits::from(test_support::static_camera());
  const ptz_state fixed{30.0, -25.0, 40.0};
  const config::seconds dt{1.0 / 15.0};
  // A box far off-centre and small: fixate and zoom would turn and zoom a lot.
  EXPECT_EQ(fixate_zoom_step(fixed, cv::Rect2d(300, 10, 4, 12), {320, 240}, limits, dt), fixed);
  EXPECT_EQ(slew_towards(fixed, {-100.0, 5.0, 80.0}, limits, config::seconds{100.0}), fixed);
}

TEST(fixate_zoom, the_step_is_what_the_head_shows_after_the_same_dt) {
  // What a node commands is what the renderer shows: the head, commanded the step's pose and
  // stepped by the same dt, arrives exactly there.
  ptz_limits limits;
  limits.pan = {-90.0, 90.0};
  const config::seconds dt{1.0 / 15.0};
  for (const auto& limits_under_test :
       {limits, ptz_limits{}, ptz_limits::from(test_support::static_camera())})
    for (const ptz_state& start : {ptz_state{0.0, -20.0, 45.0}, ptz_state{175.0, -70.0, 10.0},
                                   ptz_state{30.0, -25.0, 40.0}}) {
      ptz_camera head(limits_under_test, start);
      const auto current = head.state();
      for (const cv::Rect2d& box :
           {cv::Rect2d(300, 10, 4, 12), cv::Rect2d(0, 200, 30, 40), cv::Rect2d(150, 110, 20, 20)}) {
        const auto next = fixate_zoom_step(current, box, {320, 240}, limits_under_test, dt);
        ptz_camera moved = head;
        moved.command(next);
        moved.step(dt);
        EXPECT_EQ(moved.state(), next);
        EXPECT_TRUE(moved.settled());
      }
    }
}

}  // namespace
}  // namespace argus::vision
