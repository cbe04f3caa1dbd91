#pragma once

#include <ostream>
#include <span>
#include <string>

#include "world/layout.hpp"

namespace argus::world {

class snapshot;

/// Density, speed and flow in an area at one moment, measured as pedestrian dynamics measures
/// them with the classic method (Zhang et al. 2011, "method C"): the density is the number
/// of people whose centre lies in the area over its area, the speed their mean speed, and the
/// specific flow (persons per metre of width per second) the product of the two,
/// J_s = rho v (the hydrodynamic relation). The Voronoi method ("method D") is in
/// world/voronoi_measurement.hpp.
struct area_measurement {
  unsigned count = 0;
  double density_per_m2 = 0.0;
  double speed_mps = 0.0;
  double specific_flow_per_m_s = 0.0;
};

/// The classic-method measurement of `area` in `frame`.
area_measurement measure_area(const snapshot& frame, const box& area);

/// A named measurement area.
struct named_area {
  std::string name;
  box area;
};

/// Writes measurements as CSV, one row per area per call: `t,area,count,density_per_m2,
/// speed_mps,specific_flow_per_m_s` by the classic method, then `voronoi_density_per_m2,
/// voronoi_speed_mps,voronoi_specific_flow_per_m_s` by the Voronoi method (cut-off 1 m).
class measurement_writer {
 public:
  /// Writes the header line to `out`, which must outlive the writer.
  explicit measurement_writer(std::ostream& out);

  /// Appends one row per area, measured in `frame`.
  void write(const snapshot& frame, std::span<const named_area> areas);

 private:
  std::ostream& out_;
};

}  // namespace argus::world
