// Lines at counters (issue 18): a pedestrian reaches its place in line around an obstacle,
// along the counter's distance field, not straight through it; and leaves a line that does not
// move after behaviour_settings::queue_give_up_s.
#include <gtest/gtest.h>

#include <vector>

#include "world/behaviour.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::world {
namespace {

//   y=10 +--------------------[M]------+   M: vending machine, service point (10.5, 8.4),
//        |          +----+     :       |      line growing south
//   door |   start  |kiosk|    :       |
//        |          +----+     :       |
//   y=0  +-----------------------------+
//       x=0                           20
layout hall_with_kiosk(double service_s) {
  layout plan;
  plan.size_m = {20.0, 10.0};
  plan.regions.push_back({"hall", region_kind::waiting_room, {{0, 0}, {20, 10}}});
  plan.portals.push_back({"door", portal_kind::street, {{0, 4}, {1, 6}}});
  plan.obstacles.push_back({"kiosk", {{6, 5}, {9, 5}, {9, 9.6}, {6, 9.6}}});
  service_counter machine;
  machine.name = "machine";
  machine.footprint = {{10, 9.3}, {11, 10}};
  machine.service_point = {10.5, 8.7};
  machine.queue_direction = {0, -1};
  machine.max_queue_length = 5;
  machine.min_service_s = service_s;
  machine.max_service_s = service_s;
  plan.vending_machines.push_back(machine);
  return plan;
}

pedestrian customer(int id, const vec2& at) {
  auto p = make_pedestrian(id, 1, at, 0, -1);
  p.agenda = {goal_kind::use_vending_machine, goal_kind::leave_station};
  p.agenda_size = 2;
  p.agenda_next = 0;
  p.state.goal = goal_kind::use_vending_machine;
  return p;
}

/// Steps `people` for `seconds`, checking no one enters the kiosk; returns the events.
std::vector<event> step(const station& where, std::vector<pedestrian>& people, double seconds,
                        int& inside_kiosk) {
  behaviour_settings settings;
  std::vector<event> all;
  auto states = [&] {
    std::vector<pedestrian_state> out;
    for (const auto& p : people) out.push_back(p.state);
    return out;
  };
  snapshot now(where, 0, std::chrono::duration<double>{0.0}, states());
  for (std::uint64_t tick = 1; tick * settings.tick_s <= seconds; ++tick) {
    std::vector<event> events;
    std::vector<pedestrian> next;
    for (const auto& p : people) {
      if (auto stepped = step_pedestrian(where, now, p, settings, events)) {
        const vec2 at = stepped->state.position;
        if (at.x() > 6 && at.x() < 9 && at.y() > 5 && at.y() < 9.6) ++inside_kiosk;
        next.push_back(std::move(*stepped));
      }
    }
    people = std::move(next);
    all.insert(all.end(), events.begin(), events.end());
    now = snapshot(where, tick, std::chrono::duration<double>{tick * settings.tick_s}, states(),
                   events);
  }
  return all;
}

bool has(const std::vector<event>& events, int id, event_kind kind) {
  for (const auto& e : events) {
    if (e.pedestrian == id && e.kind == kind) return true;
  }
  return false;
}

TEST(queue, the_way_to_a_line_goes_round_an_obstacle) {
  const station where(hall_with_kiosk(5.0));
  // West of the kiosk: the straight line to the machine crosses it.
  std::vector<pedestrian> people{customer(1, {4.0, 8.0})};
  ASSERT_FALSE(where.sight_clear({4.0, 8.0}, {10.5, 8.7}));
  int inside_kiosk = 0;
  const auto events = step(where, people, 40.0, inside_kiosk);
  EXPECT_EQ(inside_kiosk, 0);
  EXPECT_TRUE(has(events, 1, event_kind::joined_queue));
  EXPECT_TRUE(has(events, 1, event_kind::service_started));
  EXPECT_TRUE(has(events, 1, event_kind::service_finished));
}

TEST(queue, a_line_that_does_not_move_is_left_after_the_timeout) {
  // The machine serves each customer for 1000 s: the second in line gives up after 180 s.
  const station where(hall_with_kiosk(1000.0));
  std::vector<pedestrian> people{customer(1, {10.5, 7.5}), customer(2, {12.0, 5.0})};
  int inside_kiosk = 0;
  const auto events = step(where, people, 200.0, inside_kiosk);
  EXPECT_TRUE(has(events, 1, event_kind::service_started));
  EXPECT_TRUE(has(events, 2, event_kind::joined_queue));
  EXPECT_FALSE(has(events, 2, event_kind::service_started));
  EXPECT_TRUE(has(events, 2, event_kind::goal_abandoned));
}

}  // namespace
}  // namespace argus::world
