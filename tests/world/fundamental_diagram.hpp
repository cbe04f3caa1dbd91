#pragma once
// Measuring the fundamental diagram as the field does (RiMEA test 4; Zhang et al. 2011's
// classic and Voronoi methods in a measurement area), shared by tests/world/rimea_test and
// bench/fundamental_diagram:
// - the free and moderate branch: a block of people at a chosen density, spread uniformly
//   over a corridor 4 m wide and 60 m long, all walking east; the area in the block's middle
//   is measured over t = 2-6 s, before the block's ends (where it thins out) reach it;
// - the congested branch: the jam in front of a 1 m exit (scenarios/validation's
//   rimea_04_fundamental_diagram), measured once a second in its three areas.

#include <vector>

#include "tests/world/experiment.hpp"
#include "world/measurement.hpp"
#include "world/voronoi_measurement.hpp"

namespace argus::world::testing {

/// One measurement: density (/m^2), speed (m/s), specific flow (/(m s)) by the classic
/// method, and the same moments by the Voronoi method (cut-off 1 m).
struct diagram_point {
  double density_per_m2 = 0.0;
  double speed_mps = 0.0;
  double specific_flow_per_m_s = 0.0;
  voronoi_measurement voronoi;
};

/// The corridor of the block experiment: 4 m x 60 m, exit at the east end.
inline layout block_corridor_layout() {
  layout plan;
  plan.name = "corridor_4x60";
  plan.size_m = {62.0, 6.0};
  plan.walls.push_back({{{1, 1}, {61, 1}, {61, 5}, {1, 5}, {1, 1}}});
  plan.regions.push_back({"corridor", region_kind::other, {{1, 1}, {61, 5}}});
  plan.portals.push_back({"east", portal_kind::street, {{60.5, 1}, {61, 5}}});
  return plan;
}

/// The block experiment at `density_per_m2` (up to about 2: random placement gets no denser).
inline diagram_point block_point(double density_per_m2, std::uint64_t seed = 1) {
  crowd_settings settings;
  settings.population = 0;
  settings.prefill = false;
  settings.run_seed = seed;
  flow block;
  block.spawn_area = {{2.0, 1.3}, {45.0, 4.7}};
  block.count = static_cast<unsigned>(density_per_m2 * 43.0 * 4.0);
  block.exit_portal = 0;
  settings.flows.push_back(block);
  experiment corridor(block_corridor_layout(), settings);
  const box area{{25.0, 1.0}, {29.0, 5.0}};
  diagram_point sum;
  int samples = 0;
  corridor.run(6.0, [&](const snapshot&, const snapshot& now) {
    const double t = now.time().count();
    if (t < 2.0 || now.tick() % 3 != 0) return;
    const auto m = measure_area(now, area);
    sum.density_per_m2 += m.density_per_m2;
    sum.speed_mps += m.speed_mps;
    sum.specific_flow_per_m_s += m.specific_flow_per_m_s;
    const auto v = measure_area_voronoi(now, area);
    sum.voronoi.density_per_m2 += v.density_per_m2;
    sum.voronoi.speed_mps += v.speed_mps;
    sum.voronoi.specific_flow_per_m_s += v.specific_flow_per_m_s;
    ++samples;
  });
  if (samples == 0) return sum;
  return {sum.density_per_m2 / samples,
          sum.speed_mps / samples,
          sum.specific_flow_per_m_s / samples,
          {sum.voronoi.density_per_m2 / samples, sum.voronoi.speed_mps / samples,
           sum.voronoi.specific_flow_per_m_s / samples}};
}

/// The jam experiment: one point per area per second with at least two people in the area
/// (by the classic method's count, for both methods: the same moments).
inline std::vector<diagram_point> jam_points() {
  experiment corridor(validation_scenario("rimea_04_fundamental_diagram.yaml"));
  std::vector<box> areas;
  for (const auto& a : corridor.scenario().world.measurement_areas) {
    areas.push_back({{a.area.min_x_m, a.area.min_y_m}, {a.area.max_x_m, a.area.max_y_m}});
  }
  std::vector<diagram_point> out;
  corridor.run(240.0, [&](const snapshot&, const snapshot& now) {
    if (now.tick() % 15 != 0) return;
    for (const auto& a : areas) {
      const auto m = measure_area(now, a);
      if (m.count >= 2) {
        out.push_back(
            {m.density_per_m2, m.speed_mps, m.specific_flow_per_m_s, measure_area_voronoi(now, a)});
      }
    }
  });
  return out;
}

/// Weidmann's (1993) fundamental diagram: v = v0 (1 - exp(-1.913 (1/rho - 1/5.4))), v0 =
/// 1.34 m/s, 0 at and above the jam density 5.4 /m^2.
inline double weidmann_speed_mps(double density_per_m2) {
  if (density_per_m2 <= 0.0) return 1.34;
  if (density_per_m2 >= 5.4) return 0.0;
  return 1.34 * (1.0 - std::exp(-1.913 * (1.0 / density_per_m2 - 1.0 / 5.4)));
}

}  // namespace argus::world::testing
