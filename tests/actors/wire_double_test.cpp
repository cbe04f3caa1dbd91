// Doubles cross processes as their bits (actors/wire_double.hpp): CAF 0.17's own packing turns
// -0.0 into 0.0, which a run across processes would write differently from one process.

#include "actors/wire_double.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "actors/wire_live.hpp"
#include "actors/wire_log.hpp"
#include "actors/wire_partition.hpp"
#include "caf/binary_deserializer.hpp"
#include "caf/binary_serializer.hpp"
#include "world/behaviour.hpp"

namespace argus::actors::testing {
namespace {

template <class T>
T crossed(T value) {
  std::vector<char> bytes;
  caf::binary_serializer sink{nullptr, bytes};
  EXPECT_FALSE(sink(value));
  T back{};
  caf::binary_deserializer source{nullptr, bytes};
  EXPECT_FALSE(source(back));
  return back;
}

TEST(wire_double, cafs_own_packing_loses_the_sign_of_zero) {
  // Why wire_double exists: if CAF ever keeps the sign, this fails and the workaround can go.
  EXPECT_FALSE(std::signbit(crossed(-0.0)));
}

TEST(wire_double, a_pose_and_a_look_cross_bit_for_bit) {
  vision::ptz_state pose;
  pose.pan_deg = -0.0;
  pose.tilt_deg = std::numeric_limits<double>::denorm_min();
  pose.field_of_view_deg = 31.25;
  auto back = crossed(pose);
  EXPECT_TRUE(std::signbit(back.pan_deg));
  EXPECT_EQ(back.tilt_deg, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(back.field_of_view_deg, 31.25);
  eval::look_record look;
  look.score = -0.0;
  look.iou = 0.1 + 0.2;
  look.box = {-0.0, 1.5, 2.0, 3.0};
  auto look_back = crossed(look);
  EXPECT_TRUE(std::signbit(look_back.score));
  EXPECT_TRUE(std::signbit(look_back.box.x));
  EXPECT_EQ(look_back.iou, 0.1 + 0.2);
  EXPECT_EQ(look_back.box.height, 3.0);
}

TEST(wire_double, a_whole_pedestrian_crosses_and_draws_what_it_would_have_drawn) {
  // A crowd partition on a worker is handed whole pedestrians: mind, timers and generator.
  world::speed_distribution speeds;
  auto p = world::make_pedestrian(17, 99, {12.5, -0.0}, 2, -1, speeds);
  p.state.velocity = {-0.0, 0.25};
  p.point = {-0.0, 3.0};
  p.has_point = true;
  p.field = 5;
  p.target_index = 3;
  p.timer_s = 0.1 + 0.2;
  p.best_distance_m = std::numeric_limits<double>::infinity();
  p.stalled_s = -0.0;
  p.blocked_s = 1.5;
  p.queued_s = 2.25;
  p.flow_exit = 4;
  partition_arrivals sent;
  sent.pedestrians.push_back(p);
  auto back = crossed(sent);
  ASSERT_EQ(back.pedestrians.size(), 1u);
  auto& q = back.pedestrians[0];
  EXPECT_EQ(q.state, p.state);
  EXPECT_TRUE(std::signbit(q.state.position.y()));
  EXPECT_TRUE(std::signbit(q.state.velocity.x()));
  EXPECT_TRUE(std::signbit(q.point.x()));
  EXPECT_TRUE(std::signbit(q.stalled_s));
  EXPECT_EQ(q.agenda, p.agenda);
  EXPECT_EQ(q.agenda_size, p.agenda_size);
  EXPECT_EQ(q.agenda_next, p.agenda_next);
  EXPECT_EQ(q.preferred_speed_mps, p.preferred_speed_mps);
  EXPECT_EQ(q.field, 5);
  EXPECT_EQ(q.target_index, 3);
  EXPECT_EQ(q.point, p.point);
  EXPECT_TRUE(q.has_point);
  EXPECT_EQ(q.timer_s, 0.1 + 0.2);
  EXPECT_EQ(q.best_distance_m, std::numeric_limits<double>::infinity());
  EXPECT_EQ(q.blocked_s, 1.5);
  EXPECT_EQ(q.queued_s, 2.25);
  EXPECT_EQ(q.entry_portal, 2);
  EXPECT_EQ(q.entry_stairs, -1);
  EXPECT_EQ(q.flow_exit, 4);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(q.random.next(), p.random.next());
}

TEST(wire_double, an_operator_order_crosses_whole) {
  // A live run's orders go out to the workers' cameras (argus serve --workers).
  operator_order order;
  order.tick = 321;
  order.camera = 7;
  order.task = 4;
  order.request.at = config::seconds{321.0 / 15.0};
  order.request.camera = 7;
  order.request.by = config::task_target::pixel;
  order.request.pixel = {-0.0, 119.5};
  order.request.cameras_wanted = 2;
  order.request.max_cameras = 3;
  order.request.cancel_at = config::seconds{0.1 + 0.2};
  auto back = crossed(order);
  EXPECT_TRUE(back.request == order.request);
  EXPECT_TRUE(std::signbit(back.request.pixel.x_px));
  EXPECT_EQ(back.tick, 321);
  EXPECT_EQ(back.task, 4u);
  EXPECT_FALSE(back.cancel);
  order.cancel = true;
  order.request.cancel_at.reset();
  order.request.by = config::task_target::first_to_enter;
  back = crossed(order);
  EXPECT_TRUE(back.cancel);
  EXPECT_FALSE(back.request.cancel_at.has_value());
  EXPECT_EQ(back.request.by, config::task_target::first_to_enter);
}

}  // namespace
}  // namespace argus::actors::testing
