#pragma once
// The fundamental diagram of stationary flow (issue 49), shared by tests/world/steady_flow_test
// and bench/steady_flow:
// - unidirectional corridors as in the Juelich corridor experiments (Zhang et al. 2011, J.
//   Stat. Mech. P06004): a corridor `width` wide fed at its west end at a controlled inflow,
//   left at its east end by an exit that may be narrower (a narrower exit backs the stream up
//   into a denser stationary state); measured in an area 2 m long across the corridor's
//   width, halfway between the entrance and the exit, once a second after a warm-up, by the
//   classic and the Voronoi method;
// - a single-file ring (Seyfried et al. 2005, J. Stat. Mech. P10002): N people in a passage
//   0.8 m wide and 17.3 m around, walked as a straight passage with periodic ends (whoever
//   leaves the east end comes back at the west end, and everyone near one end sees those
//   near the other), so the density N / L stays fixed for as long as one likes; each person's
//   speed and headway (the distance to the one ahead, centre to centre) once a second.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tests/world/experiment.hpp"
#include "tests/world/fundamental_diagram.hpp"
#include "world/behaviour.hpp"
#include "world/measurement.hpp"
#include "world/voronoi_measurement.hpp"

namespace argus::world::testing {

/// One stationary corridor experiment.
struct corridor_setup {
  double width_m = 2.4;
  /// The exit's width; the corridor's own width leaves its end open.
  double exit_width_m = 2.4;
  /// Persons per second put into the corridor's entrance area while it has room.
  double inflow_per_s = 2.0;
  std::uint64_t seed = 1;
  double warm_up_s = 60.0;
  double measure_s = 60.0;
  /// The measurement area's extent across the corridor, centred on its axis; 0 = the whole
  /// width (as the Juelich experiments measured).
  double area_width_m = 0.0;
};

/// The corridor's geometry, along y = 6 (between two navigation cells' centre lines, as the
/// bottleneck experiments are):
///
///   +-------------------------------------------+
///   | entrance   ......   area [14, 16]  ......  +--+
///   | [1, 5]                                     exit (1 m long, portal "exit" its last 0.5 m)
///   |                                            +--+
///   +-------------------------------------------+
///  x=1                                         27  28
inline constexpr double corridor_entrance_end_m = 5.0;
inline constexpr double corridor_end_m = 27.0;
inline constexpr double corridor_axis_m = 6.0;
inline constexpr double corridor_area_from_m = 14.0;
inline constexpr double corridor_area_to_m = 16.0;

inline layout stationary_corridor_layout(double width_m, double exit_width_m) {
  const double low = corridor_axis_m - width_m / 2.0;
  const double high = corridor_axis_m + width_m / 2.0;
  const bool open = exit_width_m >= width_m - 1e-9;
  // Under 0.9 m no navigation cell would be free on y = 6; centre the exit on 6.25.
  const double centre = open || exit_width_m >= 0.9 ? corridor_axis_m : corridor_axis_m + 0.25;
  const double exit_low = open ? low : centre - exit_width_m / 2.0;
  const double exit_high = open ? high : centre + exit_width_m / 2.0;
  layout plan;
  plan.name = "stationary_corridor";
  plan.size_m = {corridor_end_m + 2.0, 12.0};
  if (open) {
    plan.walls.push_back(
        {{{corridor_end_m + 1.0, low}, {1, low}, {1, high}, {corridor_end_m + 1.0, high}}});
  } else {
    plan.walls.push_back({{{corridor_end_m, exit_low},
                           {corridor_end_m, low},
                           {1, low},
                           {1, high},
                           {corridor_end_m, high},
                           {corridor_end_m, exit_high}}});
    plan.walls.push_back({{{corridor_end_m, exit_low},
                           {corridor_end_m + 1.0, exit_low},
                           {corridor_end_m + 1.0, exit_high},
                           {corridor_end_m, exit_high}}});
  }
  plan.regions.push_back({"corridor", region_kind::other, {{1, low}, {corridor_end_m, high}}});
  plan.regions.push_back({"passage",
                          region_kind::other,
                          {{corridor_end_m, exit_low}, {corridor_end_m + 1.0, exit_high}}});
  plan.portals.push_back({"exit",
                          portal_kind::street,
                          {{corridor_end_m + 0.5, exit_low}, {corridor_end_m + 1.0, exit_high}}});
  return plan;
}

/// The measurement area: 2 m of the corridor's length, `across_m` of its width on its axis.
inline box stationary_corridor_area(double across_m) {
  return {{corridor_area_from_m, corridor_axis_m - across_m / 2.0},
          {corridor_area_to_m, corridor_axis_m + across_m / 2.0}};
}

/// One point per second after the warm-up with at least two people in the area (classic
/// count; the Voronoi method measures the same moments).
inline std::vector<diagram_point> stationary_corridor_points(
    const corridor_setup& setup, const behaviour_settings& behaviour = {}) {
  crowd_settings settings;
  settings.population = 0;
  settings.prefill = false;
  settings.run_seed = setup.seed;
  settings.behaviour = behaviour;
  flow stream;
  stream.name = "inflow";
  const double half = setup.width_m / 2.0 - 0.3;
  stream.spawn_area = {{1.3, corridor_axis_m - half},
                       {corridor_entrance_end_m, corridor_axis_m + half}};
  stream.rate_per_s = setup.inflow_per_s;
  stream.count =
      static_cast<unsigned>(std::ceil(setup.inflow_per_s * (setup.warm_up_s + setup.measure_s)));
  stream.exit_portal = 0;
  settings.flows.push_back(stream);
  experiment corridor(stationary_corridor_layout(setup.width_m, setup.exit_width_m), settings);
  const box area =
      stationary_corridor_area(setup.area_width_m > 0.0 ? setup.area_width_m : setup.width_m);
  // Cells are cut at the walls, as jpsreport cuts them by the geometry.
  const box walkable{{1.0, corridor_axis_m - setup.width_m / 2.0},
                     {corridor_end_m, corridor_axis_m + setup.width_m / 2.0}};
  std::vector<diagram_point> out;
  corridor.run(
      setup.warm_up_s + setup.measure_s,
      [&](const snapshot&, const snapshot& now) {
        if (now.time().count() < setup.warm_up_s - 1e-9 || now.tick() % 15 != 0) return;
        const auto m = measure_area(now, area);
        if (m.count < 2) return;
        out.push_back({m.density_per_m2, m.speed_mps, m.specific_flow_per_m_s,
                       measure_area_voronoi(now, area, voronoi_cut_off_m, walkable)});
      },
      false);
  return out;
}

/// Seyfried et al. 2005's fit of the headway a walker in single file keeps at speed v:
/// d = 0.36 m + 1.06 s v.
inline double seyfried_headway_m(double speed_mps) {
  return 0.36 + 1.06 * speed_mps;
}

/// How far the mean headway of a speed bin may lie from the fit: about the spread of
/// Seyfried et al.'s individual points around it (their Fig. 4), our reading, not a published
/// interval.
inline constexpr double seyfried_band_m = 0.25;

/// One walker of the ring at one moment.
struct ring_sample {
  double speed_mps = 0.0;
  double headway_m = 0.0;
};

/// The ring's passage: 0.8 m wide along y = 6.25 (a navigation cell's centre line: a passage
/// this narrow has no free cell otherwise), the periodic stretch x in [4, 4 + 17.3).
inline constexpr double ring_length_m = 17.3;
inline constexpr double ring_from_m = 4.0;
inline constexpr double ring_width_m = 0.8;
inline constexpr double ring_axis_m = 6.25;

/// `people` in single file around the ring, spaced evenly at the start, stepped for
/// `warm_up_s` and then sampled once a second for `measure_s`.
inline std::vector<ring_sample> single_file_ring(int people, std::uint64_t seed,
                                                 const behaviour_settings& behaviour = {},
                                                 double warm_up_s = 30.0, double measure_s = 60.0) {
  const double to = ring_from_m + ring_length_m;
  layout plan;
  plan.name = "single_file_ring";
  plan.size_m = {to + 6.0, 12.0};
  const double low = ring_axis_m - ring_width_m / 2.0;
  const double high = ring_axis_m + ring_width_m / 2.0;
  plan.walls.push_back({{{to + 5.0, low}, {1, low}, {1, high}, {to + 5.0, high}}});
  plan.regions.push_back({"passage", region_kind::other, {{1, low}, {to + 5.0, high}}});
  plan.portals.push_back({"east", portal_kind::street, {{to + 4.5, low}, {to + 5.0, high}}});
  const station where(std::move(plan));
  std::vector<pedestrian> walkers;
  for (int i = 0; i < people; ++i) {
    const vec2 at{ring_from_m + (i + 0.5) * ring_length_m / people, ring_axis_m};
    walkers.push_back(make_flow_pedestrian(i + 1, seed, at, 0));
  }
  // The ghosts' ids lie beyond everyone's, so the tie-breaks among the real ones are the same.
  const int ghost_id = people + 1;
  const double reach_m = snapshot::neighbour_cell_m + 0.5;
  std::vector<ring_sample> out;
  std::vector<event> events;
  const double dt = behaviour.tick_s;
  const auto ticks = static_cast<std::uint64_t>(std::llround((warm_up_s + measure_s) / dt));
  for (std::uint64_t tick = 0; tick < ticks; ++tick) {
    std::vector<pedestrian_state> states;
    for (const auto& p : walkers) states.push_back(p.state);
    for (const auto& p : walkers) {
      // A copy one lap ahead or behind: nearer the goal by a lap, or farther by one.
      const double x = p.state.position.x();
      for (const double shift : {ring_length_m, -ring_length_m}) {
        if ((shift > 0.0 && x < ring_from_m + reach_m) || (shift < 0.0 && x > to - reach_m)) {
          auto ghost = p.state;
          ghost.id = ghost_id + p.state.id + (shift > 0.0 ? 0 : people);
          ghost.position.x() += shift;
          ghost.distance_to_goal_m -= shift;
          states.push_back(ghost);
        }
      }
    }
    const snapshot previous(where, tick, std::chrono::duration<double>{tick * dt},
                            std::move(states));
    for (auto& p : walkers) {
      auto next = step_pedestrian(where, previous, p, behaviour, events);
      if (!next) continue;  // cannot happen: the exit lies beyond the periodic stretch
      p = std::move(*next);
      auto& x = p.state.position.x();
      if (x >= to) x -= ring_length_m;
      if (x < ring_from_m) x += ring_length_m;
    }
    events.clear();
    const double t = static_cast<double>(tick + 1) * dt;
    if (t < warm_up_s - 1e-9 || (tick + 1) % 15 != 0) continue;
    std::vector<std::pair<double, double>> order;  // x, speed
    for (const auto& p : walkers) order.push_back({p.state.position.x(), p.state.velocity.norm()});
    std::sort(order.begin(), order.end());
    for (std::size_t i = 0; i < order.size(); ++i) {
      const double ahead =
          i + 1 < order.size() ? order[i + 1].first : order.front().first + ring_length_m;
      out.push_back({order[i].second, ahead - order[i].first});
    }
  }
  return out;
}

}  // namespace argus::world::testing
