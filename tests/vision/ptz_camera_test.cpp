#include "vision/ptz_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/vision/static_camera.hpp"

namespace argus::vision {
namespace {

camera_view view_at(double pan, double tilt, double fov) {
  camera_view v;
  v.placement.position_m = {10.0, 20.0, 5.0};
  v.pose = {pan, tilt, fov};
  v.width_px = 640;
  v.height_px = 480;
  return v;
}

TEST(ptz_camera, optical_axis_projects_to_the_image_centre) {
  // Pan 90 = north: a point due north at camera height sits on the optical axis.
  const auto v = view_at(90.0, 0.0, 60.0);
  const auto px = v.project({10.0, 50.0, 5.0});
  ASSERT_TRUE(px);
  EXPECT_NEAR(px->x(), 319.5, 1e-9);
  EXPECT_NEAR(px->y(), 239.5, 1e-9);
  // Behind the camera: no pixel.
  EXPECT_FALSE(v.project({10.0, 0.0, 5.0}));
}

TEST(ptz_camera, pan_is_counter_clockwise_and_tilt_negative_looks_down) {
  // Facing east (pan 0): north (+y) is to the left, up is up.
  const auto v = view_at(0.0, 0.0, 60.0);
  const auto left = v.project({30.0, 25.0, 5.0});
  const auto high = v.project({30.0, 20.0, 8.0});
  ASSERT_TRUE(left && high);
  EXPECT_LT(left->x(), 319.5);
  EXPECT_LT(high->y(), 239.5);
  // Tilted 45 degrees down from 5 m, the centre ray meets the floor 5 m ahead.
  const auto down = view_at(0.0, -45.0, 60.0);
  const auto floor = down.floor_point({319.5, 239.5});
  ASSERT_TRUE(floor);
  EXPECT_NEAR(floor->x(), 15.0, 1e-9);
  EXPECT_NEAR(floor->y(), 20.0, 1e-9);
}

TEST(ptz_camera, field_of_view_spans_the_image_width) {
  // A point 30 degrees left of the axis lies on the left edge at 60 degrees field of view.
  const auto v = view_at(0.0, 0.0, 60.0);
  const double a = 30.0 * M_PI / 180.0;
  const auto edge = v.project({10.0 + 10.0 * std::cos(a), 20.0 + 10.0 * std::sin(a), 5.0});
  ASSERT_TRUE(edge);
  EXPECT_NEAR(edge->x(), -0.5, 1e-9);
  // Zooming in (smaller field of view) moves the same point out of the picture.
  EXPECT_LT(view_at(0.0, 0.0, 30.0).project({20.0, 25.0, 5.0})->x(), -0.5);
}

TEST(ptz_camera, back_projection_inverts_projection) {
  const auto v = view_at(-37.0, -22.0, 48.0);
  for (const Eigen::Vector2d& pixel :
       {Eigen::Vector2d{0.0, 0.0}, Eigen::Vector2d{639.0, 479.0}, Eigen::Vector2d{100.25, 333.5}}) {
    const Eigen::Vector3d p = v.placement.position_m + 17.0 * v.back_project(pixel);
    const auto again = v.project(p);
    ASSERT_TRUE(again);
    EXPECT_NEAR((*again - pixel).norm(), 0.0, 1e-9);
  }
}

TEST(ptz_camera, commands_are_clamped_to_the_limits) {
  ptz_limits limits;
  limits.pan = {-90.0, 90.0};
  limits.tilt = {-60.0, 0.0};
  limits.field_of_view = {10.0, 60.0};
  ptz_camera camera(limits, {0.0, -20.0, 40.0});
  camera.command({120.0, -75.0, 2.0});
  EXPECT_EQ(camera.target(), (ptz_state{90.0, -60.0, 10.0}));
  for (int k = 0; k < 100; ++k) camera.step(std::chrono::duration<double>{0.1});
  EXPECT_TRUE(camera.settled());
  EXPECT_EQ(camera.state(), (ptz_state{90.0, -60.0, 10.0}));
}

TEST(ptz_camera, slewing_obeys_the_rates) {
  ptz_limits limits;  // 60 deg/s pan, 30 deg/s tilt, 20 deg/s zoom
  limits.pan = {-170.0, 170.0};
  ptz_camera camera(limits, {0.0, -20.0, 45.0});
  camera.command({100.0, -50.0, 25.0});
  camera.step(std::chrono::duration<double>{0.5});
  EXPECT_DOUBLE_EQ(camera.state().pan_deg, 30.0);
  EXPECT_DOUBLE_EQ(camera.state().tilt_deg, -35.0);
  EXPECT_DOUBLE_EQ(camera.state().field_of_view_deg, 35.0);
  camera.step(std::chrono::duration<double>{0.5});
  EXPECT_DOUBLE_EQ(camera.state().pan_deg, 60.0);
  EXPECT_DOUBLE_EQ(camera.state().tilt_deg, -50.0);  // arrived, does not overshoot
  EXPECT_DOUBLE_EQ(camera.state().field_of_view_deg, 25.0);
  // Limited pan cannot take the short way across +-180.
  ptz_camera bounded(limits, {160.0, -20.0, 45.0});
  bounded.command({-160.0, -20.0, 45.0});
  bounded.step(std::chrono::duration<double>{0.5});
  EXPECT_DOUBLE_EQ(bounded.state().pan_deg, 130.0);
}

TEST(ptz_camera, full_turn_pan_takes_the_shorter_way_round) {
  ptz_camera camera(ptz_limits{}, {170.0, -20.0, 45.0});  // default pan range -180..180
  camera.command({-170.0, -20.0, 45.0});
  camera.step(std::chrono::duration<double>{0.25});  // 15 degrees
  EXPECT_NEAR(camera.state().pan_deg, -175.0, 1e-9);
  camera.step(std::chrono::duration<double>{0.25});
  EXPECT_DOUBLE_EQ(camera.state().pan_deg, -170.0);
}

TEST(ptz_camera, static_cameras_never_move) {
  auto settings = test_support::static_camera(50.0);
  auto camera = ptz_camera::from(settings);
  camera.command({-60.0, -10.0, 20.0});
  camera.step(std::chrono::duration<double>{10.0});
  EXPECT_EQ(camera.state(), (ptz_state{30.0, -25.0, 50.0}));
  // The placement comes from the settings, for the simulator only.
  settings.position = {3.0, 4.0};
  settings.height_m = 6.0;
  EXPECT_EQ(camera_placement::from(settings).position_m, Eigen::Vector3d(3.0, 4.0, 6.0));
}

}  // namespace
}  // namespace argus::vision
