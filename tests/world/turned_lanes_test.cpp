// The turned headings' free paths two at a time are those one at a time: exactly where the
// heading stays open (it may be chosen, and its path sets the speed), and under the least a
// turn needs where it is blocked (the value then only rules the heading out).
#include "world/turned_lanes.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "world/rng.hpp"

namespace argus::world {
namespace {

constexpr double least_turn_m = 0.5;

TEST(turned_lanes, someone_straight_ahead_stops_a_path_at_contact) {
  turned_lanes lanes(least_turn_m);
  lanes.keep({1.5, 0.0}, 0.5, 2.25);  // ahead, contact 0.5: free for 1.0 m
  lanes.keep({0.5, 1.0}, 0.5, 1.25);  // beside the lane
  lanes.keep({-1.0, 0.0}, 0.5, 1.0);  // behind
  EXPECT_EQ(lanes.free_path({1.0, 0.0}, 0.9, 2.0), 1.0);
  EXPECT_EQ(lanes.free_path({-1.0, 0.0}, 0.9, 2.0), 0.5);
  EXPECT_EQ(lanes.free_path({0.0, -1.0}, 0.9, 2.0), 2.0);
}

TEST(turned_lanes, two_at_a_time_agree_with_one_at_a_time) {
  rng random(777);
  int open = 0;
  int blocked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    turned_lanes lanes(least_turn_m);
    const int people = static_cast<int>(random.below(110));  // past the capacity too
    for (int k = 0; k < people; ++k) {
      const double contact = random.uniform(0.3, 0.55);
      const vec2 offset{random.uniform(-0.5, 2.9), random.uniform(-2.9, 2.9)};
      lanes.keep(offset, contact, offset.squaredNorm());
    }
    const double angle = random.uniform(-M_PI, M_PI);
    const vec2 direction{std::cos(angle), std::sin(angle)};
    const double lane = random.uniform(0.3, 0.9);
    const double one = lanes.free_path_one_by_one(direction, lane, 2.0);
    const double two = lanes.free_path(direction, lane, 2.0);
    if (one < least_turn_m) {
      ++blocked;
      EXPECT_LT(two, least_turn_m) << trial;
    } else {
      ++open;
      EXPECT_EQ(two, one) << trial;
    }
  }
  EXPECT_GT(open, 300);
  EXPECT_GT(blocked, 300);
}

TEST(turned_lanes, past_the_capacity_the_last_are_left_out) {
  turned_lanes lanes(least_turn_m);
  for (std::size_t k = 0; k < turned_lanes::capacity; ++k) {
    lanes.keep({-1.0, 0.0}, 0.5, 1.0);  // behind: blocks nothing ahead
  }
  lanes.keep({1.0, 0.0}, 0.5, 1.0);  // one too many
  EXPECT_EQ(lanes.free_path({1.0, 0.0}, 0.9, 2.0), 2.0);
}

}  // namespace
}  // namespace argus::world
