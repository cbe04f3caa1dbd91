#pragma once

#include <optional>

#include "world/layout.hpp"

namespace argus::world {

class snapshot;

/// Density, speed and specific flow in an area at one moment by the Voronoi method (Zhang et
/// al. 2011, J. Stat. Mech. P06004, "method D", as JuPedSim's jpsreport measures it). Each
/// pedestrian i owns its Voronoi cell A_i, cut off by a circle around it, and with M the area:
///
///   rho_V = sum_i |A_i ∩ M| / |A_i| / |M|               (each person spread evenly over their
///   cell) v_V   = sum_i v_i |A_i ∩ M| / sum_i |A_i ∩ M|       (v_i = |velocity|) J_s   = rho_V v_V
///
/// Where the cells cover M (a crowd denser than one person per cut-off circle), v_V is
/// Zhang's sum_i v_i |A_i ∩ M| / |M|. Where the cut-off leaves part of M to nobody, Zhang's
/// formula counts that part as standing still (walkers at 0.25 /m^2 came out at half their
/// speed); here it is left out of the mean instead.
///
/// Someone standing just outside M still counts for the part of their cell inside it, so the
/// density changes smoothly as people cross M's edge instead of by a whole person.
struct voronoi_measurement {
  double density_per_m2 = 0.0;
  double speed_mps = 0.0;
  double specific_flow_per_m_s = 0.0;
};

/// Radius of the circle that bounds every cell unless `measure_area_voronoi` is told
/// otherwise (jpsreport's cut_by_circle and its usual radius).
inline constexpr double voronoi_cut_off_m = 1.0;

/// The Voronoi-method measurement of `area` in `frame`. Cells come from everyone's positions
/// (cv::Subdiv2D) and are cut by a regular 20-gon inscribed in the circle of radius
/// `cut_off_radius_m`, as jpsreport's cut_by_circle approximates the circle. The layout's
/// walls are not used: a cell is not clipped where a wall runs through it; it is the cut-off
/// that bounds a cell where nobody else is, next to a wall as in open space. Given `within`
/// (the walkable rectangle, such as a corridor between its walls), every cell is also cut to
/// it, as jpsreport cuts cells by the geometry: in a corridor 1.8 m wide a cell that reaches
/// past a wall otherwise counts floor nobody can stand on, and the density comes out about a
/// quarter low. People standing
/// at one point (within float precision) share that point's cell in equal parts. Zeros when
/// nobody is within the cut-off of `area`, for a box without area and for a radius <= 0.
/// Deterministic: the same snapshot gives the same numbers.
voronoi_measurement measure_area_voronoi(const snapshot& frame, const box& area,
                                         double cut_off_radius_m = voronoi_cut_off_m,
                                         const std::optional<box>& within = std::nullopt);

}  // namespace argus::world
