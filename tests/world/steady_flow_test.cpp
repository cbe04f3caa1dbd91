// The crowd in stationary flow (issue 49), at a small size of bench/steady_flow: a dense stream
// must not walk faster than people do at its density (Weidmann's curve plus 0.15 m/s) nor pass
// more than 2 persons per metre and second; single file must keep Seyfried's headway.
#include "tests/world/steady_flow.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace argus::world {
namespace {

using testing::weidmann_speed_mps;

/// Speed over Weidmann's and the specific flow, averaged over the points at `min_density` or
/// more (classic method).
struct dense_mean {
  int points = 0;
  double density = 0.0;
  double speed_over = 0.0;
  double flow = 0.0;
};

dense_mean dense_points(const std::vector<testing::diagram_point>& points, double min_density) {
  dense_mean out;
  for (const auto& p : points) {
    if (p.density_per_m2 < min_density) continue;
    ++out.points;
    out.density += p.density_per_m2;
    out.speed_over += p.speed_mps - weidmann_speed_mps(p.density_per_m2);
    out.flow += p.specific_flow_per_m_s;
  }
  if (out.points > 0) {
    out.density /= out.points;
    out.speed_over /= out.points;
    out.flow /= out.points;
  }
  return out;
}

// The set-up issue 49 was found with: 4 m wide, fed at 7 /s, measured 2 m x 2 m on the axis.
// Before, the stream's core there held 3.3 /m^2 at 0.78 m/s (Weidmann: 0.30), 2.6 /(m s). The
// bench's target is 0.15 m/s on a density bin's mean over every corridor and four seeds; this
// core alone, over 30 s of one seed, is allowed 0.2.
TEST(steady_flow, a_dense_stream_walks_no_faster_than_people_do) {
  const testing::corridor_setup setup{4.0, 4.0, 7.0, 1, 40.0, 30.0, 2.0};
  const auto m = dense_points(testing::stationary_corridor_points(setup), 1.5);
  std::printf(
      "%d points at 1.5 /m^2 or more: %.2f /m^2, speed %+.2f m/s over Weidmann's, %.2f /(m s)\n",
      m.points, m.density, m.speed_over, m.flow);
  ASSERT_GE(m.points, 20);
  EXPECT_LT(m.speed_over, 0.2);
  EXPECT_LE(m.flow, 2.0);
}

// Backed up behind an exit a third of the corridor's width: the congested branch. It must
// neither walk faster than people do nor come to a stop (the narrow corridors' congested
// branch runs about 0.1 m/s under Weidmann's curve: bench/RESULTS.md).
TEST(steady_flow, a_backed_up_stream_slows_as_people_do) {
  const testing::corridor_setup setup{2.4, 0.84, 4.8, 1, 60.0, 30.0};
  const auto points = testing::stationary_corridor_points(setup);
  const auto m = dense_points(points, 1.5);
  std::printf(
      "%d points at 1.5 /m^2 or more: %.2f /m^2, speed %+.2f m/s over Weidmann's, %.2f /(m s)\n",
      m.points, m.density, m.speed_over, m.flow);
  ASSERT_GE(m.points, 20);
  EXPECT_LT(m.speed_over, 0.15);
  EXPECT_GT(m.speed_over, -0.25);
  EXPECT_LE(m.flow, 2.0);
}

// Single file at 1.5 persons a metre: everyone is held back by the one ahead, and keeps
// about Seyfried's 0.36 m + 1.06 s v. With the headway's time gap of 0.1 s, walkers here went
// at 1.04 m/s 0.67 m apart, 0.8 m closer than people walk at that speed.
TEST(steady_flow, single_file_keeps_seyfrieds_headway) {
  const auto samples = testing::single_file_ring(26, 1, {}, 20.0, 30.0);
  double speed = 0.0;
  double headway = 0.0;
  for (const auto& s : samples) {
    speed += s.speed_mps / samples.size();
    headway += s.headway_m / samples.size();
  }
  std::printf("26 in the ring: %.2f m/s, headway %.2f m (Seyfried %.2f m)\n", speed, headway,
              testing::seyfried_headway_m(speed));
  EXPECT_NEAR(headway, testing::seyfried_headway_m(speed), testing::seyfried_band_m);
  EXPECT_LT(speed, 0.8);
}

}  // namespace
}  // namespace argus::world
