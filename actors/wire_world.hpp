#pragma once

// The world's records as they cross to a worker process (docs/distributed.md): CAF inspectors
// for a snapshot's contents, so the middleman serialises them; nothing here is hand-written
// bytes; doubles as their bits (wire_double.hpp). A snapshot itself travels as a delta
// (snapshot_delta.hpp).

#include "actors/wire_double.hpp"
#include "world/event.hpp"
#include "world/pedestrian.hpp"

namespace argus::world {

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, rgb8& x) {
  return f(x.r, x.g, x.b);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, appearance& x) {
  return f(x.shirt, x.trousers, x.skin, x.hair, actors::as_bits(x.height_m),
           actors::as_bits(x.girth_m));
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, pedestrian_state& x) {
  // vec2 is Eigen's, out of reach of argument-dependent lookup: its coordinates go one by one.
  using actors::as_bits;
  return f(x.id, x.doing, x.goal, x.counter, x.seat, as_bits(x.position.x()),
           as_bits(x.position.y()), as_bits(x.velocity.x()), as_bits(x.velocity.y()),
           as_bits(x.facing.x()), as_bits(x.facing.y()), as_bits(x.placed_heading_rad), x.look,
           x.queue_join_tick, as_bits(x.distance_to_goal_m), x.route, x.goal_serial,
           as_bits(x.squeeze_m));
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, rng& x) {
  return f(x.words());
}

// A whole pedestrian, mind and generator included, for a crowd partition on a worker
// (docs/distributed.md, "The crowd on the workers").
template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, pedestrian& x) {
  using actors::as_bits;
  return f(x.state, x.random, x.agenda, x.agenda_size, x.agenda_next,
           as_bits(x.preferred_speed_mps), x.field, x.target_index, as_bits(x.point.x()),
           as_bits(x.point.y()), x.has_point, as_bits(x.timer_s), as_bits(x.best_distance_m),
           as_bits(x.stalled_s), x.entry_portal, x.entry_stairs, x.flow_exit, as_bits(x.blocked_s),
           as_bits(x.queued_s));
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, event& x) {
  return f(x.tick, x.pedestrian, x.kind, x.goal, x.resource);
}

}  // namespace argus::world
