#include "world/experiment_layouts.hpp"

#include <fmt/format.h>

namespace argus::world {

layout bottleneck_room_layout(double exit_width_m) {
  // Centred between two navigation cells' centre lines (y = 6), as the YAML experiments are;
  // an exit under 0.9 m leaves no free cell there (cells are 0.5 m, blocked within 0.2 m of a
  // wall), so it is centred on a cell's centre line (y = 6.25) instead.
  const double centre = exit_width_m < 0.9 ? 6.25 : 6.0;
  const double low = centre - exit_width_m / 2.0;
  const double high = centre + exit_width_m / 2.0;
  layout plan;
  plan.name = fmt::format("bottleneck_{}m", exit_width_m);
  plan.size_m = {13.0, 12.0};
  plan.walls.push_back({{{11, low}, {11, 1}, {1, 1}, {1, 11}, {11, 11}, {11, high}}});
  plan.walls.push_back({{{11, low}, {12, low}, {12, high}, {11, high}}});
  plan.regions.push_back({"room", region_kind::other, {{1, 1}, {11, 11}}});
  plan.regions.push_back({"passage", region_kind::other, {{11, low}, {12, high}}});
  plan.portals.push_back({"exit", portal_kind::street, {{11.5, low}, {12, high}}});
  return plan;
}

box bottleneck_room_area() {
  return {{1.3, 1.3}, {10.7, 10.7}};
}

}  // namespace argus::world
