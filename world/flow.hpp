#pragma once

#include <string>

#include "world/layout.hpp"

namespace argus::world {

/// A stream of pedestrians for a standard experiment (corridor, corner, bottleneck,
/// evacuation), as JuPedSim and Vadere users define them: `count` pedestrians appear at free
/// spots of `spawn_area`, all at once (`rate_per_s` = 0) or `rate_per_s` per second from
/// `start_s` on, and each walks to portal `exit_portal` and leaves there. Flow pedestrians
/// have no errands: their whole agenda is that exit.
struct flow {
  std::string name;
  box spawn_area;
  unsigned count = 0;
  double rate_per_s = 0.0;
  double start_s = 0.0;
  /// Index into the layout's portals; -1 = the portal named `exit_name`.
  int exit_portal = -1;
  std::string exit_name;
};

}  // namespace argus::world
