#include "world/measurement.hpp"

#include <fmt/format.h>

#include "world/snapshot.hpp"
#include "world/voronoi_measurement.hpp"

namespace argus::world {

area_measurement measure_area(const snapshot& frame, const box& area) {
  area_measurement out;
  double speed_sum = 0.0;
  for (const auto& p : frame.pedestrians()) {
    if (!area.contains(p.position)) continue;
    ++out.count;
    speed_sum += p.velocity.norm();
  }
  const vec2 size = area.max - area.min;
  const double square_m = size.x() * size.y();
  if (square_m <= 0.0) return out;
  out.density_per_m2 = out.count / square_m;
  out.speed_mps = out.count > 0 ? speed_sum / out.count : 0.0;
  out.specific_flow_per_m_s = out.density_per_m2 * out.speed_mps;
  return out;
}

measurement_writer::measurement_writer(std::ostream& out) : out_(out) {
  // The Voronoi columns come last, so readers of the classic ones find them where they were.
  out_ << "t,area,count,density_per_m2,speed_mps,specific_flow_per_m_s,voronoi_density_per_m2,"
          "voronoi_speed_mps,voronoi_specific_flow_per_m_s\n";
}

void measurement_writer::write(const snapshot& frame, std::span<const named_area> areas) {
  for (const auto& a : areas) {
    const auto m = measure_area(frame, a.area);
    const auto v = measure_area_voronoi(frame, a.area);
    out_ << fmt::format("{},{},{},{},{},{},{},{},{}\n", frame.time().count(), a.name, m.count,
                        m.density_per_m2, m.speed_mps, m.specific_flow_per_m_s, v.density_per_m2,
                        v.speed_mps, v.specific_flow_per_m_s);
  }
}

}  // namespace argus::world
