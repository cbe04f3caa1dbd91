#pragma once

#include "config/scenario.hpp"
#include "world/layout.hpp"

namespace argus::world {
class station;
}

namespace argus::eval {

/// The smallest a pedestrian may appear (pixels tall) at the camera's narrowest field of view
/// for the oracle to count her as seeable.
inline constexpr double min_reachable_height_px = 16.0;

/// Whether `camera` could see a pedestrian `height_m` tall standing at `where` at some pan,
/// tilt and zoom within its limits (the oracle bound of docs/metrics.md): no wall on the line
/// of sight, her centre within the pan and tilt ranges widened by half the widest field of
/// view, and at least min_reachable_height_px tall at the narrowest. Other pedestrians are not
/// counted as obstacles: a head can wait for a gap.
bool reachable(const config::camera_settings& camera, const world::station& station,
               const world::vec2& where, double height_m);

}  // namespace argus::eval
