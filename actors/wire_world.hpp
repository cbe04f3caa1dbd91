#pragma once

// The world's records as they cross to a worker process (docs/distributed.md): CAF inspectors
// for a snapshot's contents, so the middleman serialises them; nothing here is hand-written
// bytes. A snapshot itself travels as a delta (snapshot_delta.hpp), its pedestrians with their
// doubles as bits.

#include "world/event.hpp"
#include "world/pedestrian.hpp"

namespace argus::world {

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, rgb8& x) {
  return f(x.r, x.g, x.b);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, event& x) {
  return f(x.tick, x.pedestrian, x.kind, x.goal, x.resource);
}

}  // namespace argus::world
