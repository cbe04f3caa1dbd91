#pragma once

#include "world/pedestrian.hpp"

namespace argus::world {

/// What a walker reads of the people around it, packed into one cache line. The snapshot keeps
/// these in its neighbour index's cell order, so a walker's 3 x 3 cells are one sequential
/// read instead of a jump per person into 144-byte states in id order (at 10,000 pedestrians
/// those jumps were most of the crowd's time).
struct alignas(64) neighbour {
  vec2 position{0.0, 0.0};
  vec2 velocity{0.0, 0.0};
  double radius = 0.0;
  double distance_to_goal_m = 0.0;
  int id = 0;
  int route = -1;
  int counter = -1;
  activity doing = activity::walking;

  neighbour() = default;
  explicit neighbour(const pedestrian_state& p)
      : position(p.position),
        velocity(p.velocity),
        radius(p.radius_m()),
        distance_to_goal_m(p.distance_to_goal_m),
        id(p.id),
        route(p.route),
        counter(p.counter),
        doing(p.doing) {}

  /// The same value as pedestrian_state::radius_m().
  double radius_m() const noexcept { return radius; }
};

static_assert(sizeof(neighbour) == 64);

}  // namespace argus::world
