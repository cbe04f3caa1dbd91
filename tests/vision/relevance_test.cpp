#include "vision/relevance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/vision/static_camera.hpp"

namespace argus::vision {
namespace {

// pan [-60, 60], tilt [-80, 10], fov [5, 45]: mid-ranges 0, -35, 25.
ptz_limits camera() {
  config::camera_settings c;
  c.pan_limits = {-60.0, 60.0};
  c.tilt_limits = {-80.0, 10.0};
  c.field_of_view_limits = {5.0, 45.0};
  return ptz_limits::from(c);
}

TEST(relevance, one_at_the_centre_of_the_ranges) {
  config::controller_settings controller;
  EXPECT_DOUBLE_EQ(relevance({0.0, -35.0, 25.0}, camera(), controller, camera_availability::free),
                   1.0);
}

TEST(relevance, zero_when_busy) {
  config::controller_settings controller;
  EXPECT_EQ(relevance({0.0, -35.0, 25.0}, camera(), controller, camera_availability::busy), 0.0);
}

TEST(relevance, eq1_with_sigma_5) {
  config::controller_settings controller;  // sigmas 5.0 (the paper's)
  // One sigma off in pan: exp(-1/2).
  EXPECT_NEAR(relevance({5.0, -35.0, 25.0}, camera(), controller, camera_availability::free),
              std::exp(-0.5), 1e-12);
  // At the field-of-view limit: 20 degrees = 4 sigma off: exp(-8).
  EXPECT_NEAR(relevance({0.0, -35.0, 45.0}, camera(), controller, camera_availability::free),
              std::exp(-8.0), 1e-15);
  EXPECT_NEAR(relevance({0.0, -35.0, 5.0}, camera(), controller, camera_availability::free),
              std::exp(-8.0), 1e-15);
  // At the tilt limit, 45 degrees off: exp(-81/2); the terms add in the exponent.
  EXPECT_NEAR(relevance({5.0, 10.0, 25.0}, camera(), controller, camera_availability::free),
              std::exp(-0.5 - 40.5), 1e-20);
  // At the pan limit: 60 degrees = 12 sigma.
  EXPECT_NEAR(relevance({60.0, -35.0, 25.0}, camera(), controller, camera_availability::free),
              std::exp(-72.0), 1e-35);
}

TEST(relevance, spreads_come_from_controller_settings) {
  config::controller_settings controller;
  controller.relevance_sigma_pan_deg = 10.0;
  controller.relevance_sigma_tilt_deg = 20.0;
  controller.relevance_sigma_fov_deg = 2.0;
  EXPECT_NEAR(relevance({10.0, -15.0, 27.0}, camera(), controller, camera_availability::free),
              std::exp(-0.5 - 0.5 - 0.5), 1e-12);
}

TEST(relevance, a_static_camera_is_judged_from_its_fixed_pose) {
  // Its limits collapse onto its pose (pan 30, tilt -25, fov 40): the hat values of eq. (1).
  const auto limits = ptz_limits::from(test_support::static_camera());
  config::controller_settings controller;
  EXPECT_DOUBLE_EQ(relevance({30.0, -25.0, 40.0}, limits, controller, camera_availability::free),
                   1.0);
  // One sigma off in pan and in field of view: exp(-1/2 - 1/2).
  EXPECT_NEAR(relevance({35.0, -25.0, 35.0}, limits, controller, camera_availability::free),
              std::exp(-1.0), 1e-12);
}

TEST(relevance, a_pan_that_turns_all_the_way_round_costs_no_leeway) {
  ptz_limits limits;  // pan [-180, 180]: wraps
  limits.tilt = {-80.0, 10.0};
  limits.field_of_view = {5.0, 45.0};
  config::controller_settings controller;
  for (double pan : {0.0, 90.0, -165.0, 355.0})
    EXPECT_DOUBLE_EQ(relevance({pan, -35.0, 25.0}, limits, controller, camera_availability::free),
                     1.0)
        << pan;
  // The other terms still count: one sigma off in tilt.
  EXPECT_NEAR(relevance({90.0, -30.0, 25.0}, limits, controller, camera_availability::free),
              std::exp(-0.5), 1e-12);
}

}  // namespace
}  // namespace argus::vision
