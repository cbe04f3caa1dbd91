#pragma once

#include <Eigen/Core>
#include <vector>

#include "world/pedestrian.hpp"

namespace argus::vision {

/// One instance of the unit cube ([-0.5, 0.5]^3) the figures are built from: its model
/// transform (column-major, as OpenGL takes it) and its colour (RGB in [0, 1]).
struct box_instance {
  float model[16];
  float color[3];
};

/// The unit cube as 36 vertices (position, normal) for glDrawArraysInstanced.
const std::vector<float>& unit_cube_vertices();

/// Appends the low-poly articulated figure of pedestrian `p` at time `time_s`:
///
///            [hair]
///            [head]        skin
///     [arm][ torso ][arm]  shirt (arms: sleeves in shirt colour, hands in skin)
///           [leg][leg]     trousers
///
/// scaled by the appearance's height and girth, turned to the heading. Walking swings the
/// legs and arms about hip and shoulder, phase from time and speed (a stride of about 1.4 m),
/// so two frames half a tick apart differ; a sitting pedestrian bends at hip and knee.
void append_pedestrian(const world::pedestrian_state& p, double time_s,
                       std::vector<box_instance>& out);

/// A box of `size` (x, y, z extents) centred at `centre`, axis-aligned, of `color`.
box_instance make_box(const Eigen::Vector3d& centre, const Eigen::Vector3d& size,
                      const Eigen::Vector3f& color);

}  // namespace argus::vision
