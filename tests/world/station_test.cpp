// The station's navigation: every target is reachable, routes descend the distance field and
// never lead through walls (zero-thickness walls between two free grid cells included).
#include "world/station.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "world/layout_loader.hpp"
#include "world/rng.hpp"

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

TEST(station, the_walking_distance_is_the_best_cell_in_sight_plus_the_straight_walk) {
  // distance_to's definition, checked by brute force in the open (where it tests no line of
  // sight) and beside walls and jambs (where it does): of the 3 x 3 cells around p, those in
  // sight, each the cell's field value plus the straight walk to its centre.
  const auto& where = penn();
  const double cell = where.cell_m();
  const int field = where.target(target_kind::stairs, 2);
  rng draw(11);
  int checked = 0;
  int beside_walls = 0;
  for (int i = 0; i < 4000; ++i) {
    const vec2 p{draw.uniform(1.0, 199.0), draw.uniform(1.0, 99.0)};
    if (!where.walkable(p)) continue;
    const int cx = static_cast<int>(p.x() / cell);
    const int cy = static_cast<int>(p.y() / cell);
    double expected = std::numeric_limits<double>::infinity();
    bool all_in_sight = true;
    for (int y = cy - 1; y <= cy + 1; ++y) {
      for (int x = cx - 1; x <= cx + 1; ++x) {
        const vec2 centre{(x + 0.5) * cell, (y + 0.5) * cell};
        if (!where.line_clear(p, centre)) {
          all_in_sight = false;
          continue;
        }
        expected = std::min(expected, where.field_at(field, x, y) + (centre - p).norm());
      }
    }
    ASSERT_EQ(where.distance_to(field, p), expected) << p.transpose();
    ++checked;
    beside_walls += all_in_sight ? 0 : 1;
  }
  EXPECT_GT(checked, 2000);
  EXPECT_GT(beside_walls, 20);
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
  EXPECT_THROW(station{plan}, config::scenario_error);
}

/// A 20 m x 10 m hall with a street door on its west wall, for the layout checks.
layout small_hall() {
  layout plan;
  plan.source_path = "hall.yaml";
  plan.size_m = {20.0, 10.0};
  plan.regions.push_back({"hall", region_kind::waiting_room, {{0, 0}, {20, 10}}});
  plan.portals.push_back({"door", portal_kind::street, {{0, 4}, {1, 6}}});
  return plan;
}

/// The problems station{plan} reports, as "field: message" lines.
std::vector<std::string> problems_of(const layout& plan) {
  try {
    station built{plan};
  } catch (const config::scenario_error& e) {
    std::vector<std::string> out;
    for (const auto& p : e.problems()) {
      EXPECT_EQ(p.file, "hall.yaml");
      out.push_back(p.field + ": " + p.message);
    }
    return out;
  }
  return {};
}

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

TEST(station, the_shipped_layout_passes_every_check) {
  EXPECT_TRUE(problems_of([] {
                auto plan = load_layout(builtin_layout_path());
                plan.source_path = "hall.yaml";
                return plan;
              }())
                  .empty());
}

TEST(station, the_fields_are_the_same_whatever_the_threads_that_compute_them) {
  // The fields are computed side by side: each must land in its own target's place, whole.
  navigation_settings one_thread;
  one_thread.threads = 1;
  navigation_settings three_threads;
  three_threads.threads = 3;
  const auto alone = station::load(builtin_layout_path(), one_thread);
  const auto shared = station::load(builtin_layout_path(), three_threads);
  const auto& plan = alone->plan();
  const std::vector<std::pair<target_kind, std::size_t>> kinds{
      {target_kind::portal, plan.portals.size()},
      {target_kind::stairs, plan.stairways.size()},
      {target_kind::counter, alone->counter_count()},
      {target_kind::bench, plan.benches.size()},
      {target_kind::meeting_point, plan.meeting_points.size()}};
  int compared = 0;
  for (const auto& [kind, count] : kinds) {
    for (std::size_t i = 0; i < count; ++i) {
      const int field = alone->target(kind, i);
      ASSERT_EQ(field, shared->target(kind, i));
      for (double x = 0.25; x < plan.size_m.x(); x += 1.3) {
        for (double y = 0.25; y < plan.size_m.y(); y += 1.3) {
          const vec2 p{x, y};
          ASSERT_EQ(alone->distance_to(field, p), shared->distance_to(field, p))
              << "field " << field << " at " << p.transpose();
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 100000);
}

TEST(station, stairs_behind_a_wall_are_unreachable_from_the_entrance) {
  auto plan = small_hall();
  // A wall right across the hall at x = 15 shuts the stairs in the east end away.
  plan.walls.push_back({{{15, 0}, {15, 10}}});
  plan.stairways.push_back({"platform", {{17, 4}, {19, 6}}});
  const auto problems = problems_of(plan);
  EXPECT_TRUE(mentions(problems,
                       "stairs[0]: 'platform' cannot be reached on foot from "
                       "entrance 'door' (portals[0])"))
      << ::testing::PrintToString(problems);
}

TEST(station, stairs_with_no_floor_inside_are_rejected) {
  auto plan = small_hall();
  plan.size_m = {30.0, 10.0};
  // Just outside the hall: the target would snap to the hall's nearest cell, but nobody
  // would ever stand inside the box to leave.
  plan.stairways.push_back({"platform", {{20.5, 4}, {22, 6}}});
  const auto problems = problems_of(plan);
  EXPECT_TRUE(mentions(problems, "stairs[0]: 'platform' has no walkable floor inside its box"))
      << ::testing::PrintToString(problems);
}

TEST(station, a_line_through_an_obstacle_is_rejected) {
  auto plan = small_hall();
  service_counter machine;
  machine.name = "ticket_machine";
  machine.footprint = {{10, 9}, {11, 10}};
  machine.service_point = {10.5, 8.4};
  machine.queue_direction = {0, -1};
  machine.max_queue_length = 8;
  plan.vending_machines.push_back(machine);
  // A kiosk 3 m down the line.
  plan.obstacles.push_back({"kiosk", {{9, 4}, {12, 4}, {12, 6}, {9, 6}}});
  const auto problems = problems_of(plan);
  EXPECT_TRUE(mentions(problems, "vending_machines[0]: 'ticket_machine': slot 3 of its line"))
      << ::testing::PrintToString(problems);
}

TEST(station, a_street_door_inside_the_hall_is_rejected) {
  auto plan = small_hall();
  plan.portals.push_back({"middle", portal_kind::street, {{9, 4}, {11, 6}}});
  plan.portals.push_back({"nowhere", portal_kind::internal, {{14, 4}, {15, 6}}});
  const auto problems = problems_of(plan);
  EXPECT_TRUE(mentions(problems, "portals[1]: street portal 'middle' does not touch the edge"))
      << ::testing::PrintToString(problems);
  EXPECT_TRUE(mentions(problems, "portals[2]: internal portal 'nowhere' overlaps 1 walkable"))
      << ::testing::PrintToString(problems);
  EXPECT_FALSE(mentions(problems, "portals[0]"));
}

TEST(station, the_walk_along_a_narrow_corridor_points_along_it) {
  // A corridor 2 m wide: every cell is near a wall; the descent must not lean into one.
  layout plan;
  plan.size_m = {30.0, 4.0};
  plan.walls.push_back({{{1, 1}, {29, 1}, {29, 3}, {1, 3}, {1, 1}}});
  plan.regions.push_back({"corridor", region_kind::other, {{1, 1}, {29, 3}}});
  plan.portals.push_back({"end", portal_kind::street, {{28.5, 1}, {29, 3}}});
  const station corridor{plan};
  const int field = corridor.target(target_kind::portal, 0);
  for (double x = 3.0; x < 26.0; x += 0.37) {
    const vec2 way = corridor.direction_to(field, {x, 2.0});
    EXPECT_GT(way.x(), 0.97) << x;  // within 14 degrees of straight along
  }
}

}  // namespace
}  // namespace argus::world
