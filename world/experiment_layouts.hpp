#pragma once

#include "world/layout.hpp"

namespace argus::world {

/// Layouts of the standard bottleneck experiment, built in code so a sweep over the exit
/// width needs no file per width (the fixed ones are YAML in scenarios/validation/layouts).
///
///   y=11 +----------+
///        |          +--+
///        |   room   exit  (width w, 1 m long, centred at y = 6; 6.25 under 0.9 m)
///        |          +--+
///   y=1  +----------+
///       x=1        11  12
///
/// The room is 10 m x 10 m; the exit passage ends in the street portal "exit" (its last
/// 0.5 m), as in the bottleneck experiments of Kretz et al. (2006) and Seyfried et al. (2009).
layout bottleneck_room_layout(double exit_width_m);

/// The room of bottleneck_room_layout, where people are placed at the start.
box bottleneck_room_area();

}  // namespace argus::world
