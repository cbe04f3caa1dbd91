// Doubles cross processes as their bits (actors/wire_double.hpp): CAF 0.17's own packing turns
// -0.0 into 0.0, which a run across processes would write differently from one process.

#include "actors/wire_double.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "actors/wire_log.hpp"
#include "caf/binary_deserializer.hpp"
#include "caf/binary_serializer.hpp"

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

}  // namespace
}  // namespace argus::actors::testing
