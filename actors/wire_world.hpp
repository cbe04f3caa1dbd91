#pragma once

// The world's records as they cross to a worker process (docs/distributed.md): CAF inspectors
// for a snapshot's contents, so the middleman serialises them; nothing here is hand-written
// bytes. A snapshot itself holds indices built from its pedestrians, so what travels is what
// it was built from, and the receiver builds the same object again.

#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

#include "world/event.hpp"
#include "world/pedestrian.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::world {

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, rgb8& x) {
  return f(x.r, x.g, x.b);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, appearance& x) {
  return f(x.shirt, x.trousers, x.skin, x.hair, x.height_m, x.girth_m);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, pedestrian_state& x) {
  // vec2 is Eigen's, out of reach of argument-dependent lookup: its coordinates go one by one.
  return f(x.id, x.doing, x.goal, x.counter, x.seat, x.position.x(), x.position.y(), x.velocity.x(),
           x.velocity.y(), x.facing.x(), x.facing.y(), x.placed_heading_rad, x.look,
           x.queue_join_tick, x.distance_to_goal_m, x.route, x.goal_serial, x.squeeze_m);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, event& x) {
  return f(x.tick, x.pedestrian, x.kind, x.goal, x.resource);
}

}  // namespace argus::world

namespace argus::actors {

/// What a snapshot is built from: `world::snapshot`'s constructor arguments but the station,
/// which the receiver has.
struct wire_snapshot {
  std::uint64_t tick = 0;
  double time_s = 0.0;
  std::vector<world::pedestrian_state> pedestrians;
  std::vector<world::event> events;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, wire_snapshot& x) {
  return f(x.tick, x.time_s, x.pedestrians, x.events);
}

inline wire_snapshot to_wire(const world::snapshot& s) {
  wire_snapshot w;
  w.tick = s.tick();
  w.time_s = s.time().count();
  w.pedestrians.assign(s.pedestrians().begin(), s.pedestrians().end());
  w.events.assign(s.events().begin(), s.events().end());
  return w;
}

inline std::shared_ptr<const world::snapshot> from_wire(const world::station& where,
                                                        wire_snapshot w) {
  return std::make_shared<const world::snapshot>(where, w.tick,
                                                 std::chrono::duration<double>{w.time_s},
                                                 std::move(w.pedestrians), std::move(w.events));
}

}  // namespace argus::actors
