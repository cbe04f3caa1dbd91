#include "vision/floor_estimate.hpp"

#include <gtest/gtest.h>

namespace argus::vision {
namespace {

// A camera 8 m up at (0, 0), looking east and down, as the station's PTZ cameras do.
camera_view station_view(double tilt_deg = -20.0) {
  camera_view v;
  v.placement.position_m = {0.0, 0.0, 8.0};
  v.pose = {0.0, tilt_deg, 40.0};
  v.width_px = 320;
  v.height_px = 240;
  return v;
}

// The box a body `height_m` tall standing at `feet` fills in `view` (a third as wide as tall).
cv::Rect2d body_box(const camera_view& view, const Eigen::Vector2d& feet, double height_m) {
  const auto bottom = view.project({feet.x(), feet.y(), 0.0});
  const auto top = view.project({feet.x(), feet.y(), height_m});
  EXPECT_TRUE(bottom && top);
  const double h = bottom->y() - top->y();
  return {bottom->x() - h / 6.0, top->y(), h / 3.0, h};
}

TEST(floor_estimate, a_box_is_put_where_the_feet_stand) {
  const auto view = station_view();
  const Eigen::Vector2d feet{25.0, 3.0};
  const auto e = floor_estimate_of(view, body_box(view, feet, 1.7), 42);
  ASSERT_TRUE(e);
  EXPECT_LT((e->where - feet).norm(), 0.05);
  EXPECT_EQ(e->tick, 42);
  // Farther away the same four pixels cover more floor.
  const auto far = floor_estimate_of(view, body_box(view, {40.0, 3.0}, 1.7), 42);
  ASSERT_TRUE(far);
  EXPECT_GT(e->radius_m, 0.0);
  EXPECT_GT(far->radius_m, e->radius_m);
}

TEST(floor_estimate, feet_cut_off_are_put_under_the_head_at_the_assumed_height) {
  const auto view = station_view();
  const Eigen::Vector2d feet{25.0, 3.0};
  auto box = body_box(view, feet, 1.7);
  // Her lower half below the frame: the box ends at the frame's bottom edge.
  box.height = view.height_px - box.y;
  const auto e = floor_estimate_of(view, box, 0);
  ASSERT_TRUE(e);
  // Off the optical axis a tilted camera sees her leaning: her head is not quite above the
  // box's centre, a few centimetres on the floor.
  EXPECT_LT((e->where - feet).norm(), 0.1);
  // A body 1.9 m tall read as 1.7 m: off, but within the radius given for it.
  auto tall = body_box(view, feet, 1.9);
  tall.height = view.height_px - tall.y;
  const auto t = floor_estimate_of(view, tall, 0);
  ASSERT_TRUE(t);
  EXPECT_GT(t->radius_m, 0.3);
  EXPECT_GT((t->where - feet).norm(), 0.1);
}

TEST(floor_estimate, a_box_above_the_horizon_has_no_floor_point) {
  const auto view = station_view(10.0);  // looking up
  EXPECT_FALSE(floor_estimate_of(view, cv::Rect2d(150, 10, 10, 30), 0));
}

TEST(floor_estimate, a_find_can_be_her_within_the_radii_the_slack_and_her_walk) {
  const floor_rules rules{1.7, 2.0, 3.0, 10.0};
  const floor_estimate expected{{10.0, 0.0}, 0.5, 0};
  const auto at = [](double x) { return floor_estimate{{x, 0.0}, 0.5, 15}; };
  EXPECT_TRUE(could_be(at(13.9), expected, 0.0, rules));  // 0.5 + 0.5 + 3
  EXPECT_FALSE(could_be(at(14.1), expected, 0.0, rules));
  EXPECT_TRUE(could_be(at(15.9), expected, 1.0, rules));  // and 2 m walked in a second
  EXPECT_FALSE(could_be(at(16.1), expected, 1.0, rules));
}

// Once the group has lost her and its estimate is no longer trusted, whoever it takes next is
// not confirmed, and stays so along the chain of finds tested against him: a group on a
// stranger does not refuse her where she is found again.
TEST(floor_estimate, only_a_chain_of_finds_from_the_operators_pick_is_confirmed) {
  floor_estimate expected{{0.0, 0.0}, 0.5, 0};
  EXPECT_TRUE(confirmed_by(std::nullopt, true));    // the operator's pick
  EXPECT_FALSE(confirmed_by(std::nullopt, false));  // after the group's estimate expired
  EXPECT_TRUE(confirmed_by(expected, false));
  expected.confirmed = false;
  EXPECT_FALSE(confirmed_by(expected, false));
}

}  // namespace
}  // namespace argus::vision
