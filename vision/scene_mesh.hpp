#pragma once

#include <cstddef>
#include <vector>

#include "world/layout.hpp"

namespace argus::vision {

/// One vertex of the renderer's triangle lists: world position, face normal and colour (RGB
/// in [0, 1]); `pattern` = 1 asks the shader for the floor's tile pattern.
struct mesh_vertex {
  float position[3];
  float normal[3];
  float color[3];
  float pattern;
};

/// The station's static geometry as flat-shaded triangles, in two parts drawn differently:
/// `floor` (coplanar layers at z = 0, drawn in order with the depth test off so no layer
/// z-fights with the one under it) and `solids` (walls, obstacles, counters, benches, depth
/// tested).
struct scene_mesh {
  std::vector<mesh_vertex> floor;
  std::vector<mesh_vertex> solids;
};

/// Heights of the extruded parts, in metres.
struct scene_heights {
  double wall_m = 7.0;
  double column_m = 9.0;
  double kiosk_m = 2.6;
  double bench_m = 0.45;
  double ticket_booth_m = 2.4;
  double vending_machine_m = 1.9;
  double other_obstacle_m = 1.2;
};

/// Builds the mesh of `plan`: the floor tinted per region kind (tracks dark, platforms grey,
/// halls in stone colours), portals as yellow floor marks, stairs as striped dark patches;
/// walls as 0.3 m thick slabs; obstacles extruded (columns tall, kiosks, bench pairs low);
/// ticket booths, vending machines and benches as boxes.
scene_mesh build_scene_mesh(const world::layout& plan, const scene_heights& heights = {});

}  // namespace argus::vision
