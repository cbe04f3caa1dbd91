// The station's navigation: every target is reachable, routes descend the distance field and
// never lead through walls (zero-thickness walls between two free grid cells included).
#include "world/station.hpp"

#include <gtest/gtest.h>

#include "world/layout_loader.hpp"

namespace argus::world {
namespace {

const station& penn() {
  static const auto shared = station::load(builtin_layout_path());
  return *shared;
}

TEST(station, following_the_field_reaches_every_stairs_from_the_arcade) {
  const auto& where = penn();
  for (std::size_t s = 0; s < where.plan().stairways.size(); ++s) {
    const int field = where.target(target_kind::stairs, s);
    vec2 p{190.0, 50.0};
    const double start = where.distance_to(field, p);
    EXPECT_GT(start, 150.0);
    int steps = 0;
    while (!where.plan().stairways[s].area.contains(p) && steps < 5000) {
      const vec2 next = p + 0.1 * where.direction_to(field, p);
      ASSERT_TRUE(where.line_clear(p, next)) << "through a wall at " << p.transpose();
      p = next;
      ++steps;
    }
    EXPECT_TRUE(where.plan().stairways[s].area.contains(p)) << where.plan().stairways[s].name;
    // The path is not much longer than the field says.
    EXPECT_LT(steps * 0.1, start * 1.15);
  }
}

TEST(station, walls_block_the_grid_across_them) {
  const auto& where = penn();
  // Just west and just east of the concourse/waiting-room wall at x = 65, away from portals:
  // the route between the two points goes round through a portal, not 0.6 m across.
  const int field = where.target(target_kind::stairs, 2);  // platform_3, west of the wall
  const double west = where.distance_to(field, {64.7, 35.0});
  const double east = where.distance_to(field, {65.3, 35.0});
  EXPECT_GT(east - west, 10.0);
  EXPECT_FALSE(where.line_clear({64.7, 35.0}, {65.3, 35.0}));
  EXPECT_TRUE(where.line_clear({64.7, 23.0}, {65.3, 23.0}));  // through the portal
}

TEST(station, fits_and_seats) {
  const auto& where = penn();
  EXPECT_TRUE(where.fits({100.0, 50.0}, 0.25));
  EXPECT_FALSE(where.fits({10.0, 50.0}, 0.25));   // tracks
  EXPECT_FALSE(where.fits({65.1, 35.0}, 0.25));   // on a wall
  EXPECT_FALSE(where.fits({170.0, 20.0}, 0.25));  // outside every region
  EXPECT_EQ(where.seats().size(), 72u);
  EXPECT_EQ(where.counter_count(), 10u);
  EXPECT_FALSE(where.is_vending_machine(3));
  EXPECT_TRUE(where.is_vending_machine(4));
}

TEST(station, cut_off_target_is_rejected) {
  layout plan;
  plan.size_m = {20.0, 10.0};
  plan.regions.push_back({"hall", region_kind::waiting_room, {{0, 0}, {20, 10}}});
  plan.portals.push_back({"door", portal_kind::street, {{0, 4}, {1, 6}}});
  // A closed box around the meeting point cuts it off.
  plan.walls.push_back({{{14, 4}, {16, 4}, {16, 6}, {14, 6}, {14, 4}}});
  plan.meeting_points.push_back({"trapped", {15, 5}, 0.5});
  EXPECT_THROW(station{plan}, std::invalid_argument);
}

}  // namespace
}  // namespace argus::world
