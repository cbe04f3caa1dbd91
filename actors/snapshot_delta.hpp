#pragma once

// A snapshot as it crosses to the workers (docs/distributed.md): what changed since the one
// before it. The whole crowd as CAF serialises it cost about 11 ms a side for 10,000 people
// (one call per field, 33 fields a person), every tick, on the run's critical path; most people
// only moved, and a seated or queueing one did not even do that. The receiver rebuilds the same
// pedestrians, bit for bit, and the same snapshot from them.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "actors/wire_world.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::actors {

// Doubles cross as their bits: CAF 0.17 writes a double through a portable IEEE 754 packing
// that drops the sign of zero (-0.0 arrives as 0.0), and a heading drawn from a facing of -0.0
// is not the one drawn from 0.0.

/// The fields a step changes in a walker, as bits: position, velocity and facing (x, y each),
/// distance to the goal, squeeze. Everything else stays as it was.
struct moved_state {
  std::array<std::uint64_t, 8> bits{};
  friend bool operator==(const moved_state&, const moved_state&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, moved_state& x) {
  return f(x.bits);
}

/// A whole pedestrian (`world::pedestrian_state`) as it crosses.
struct wire_pedestrian {
  int id = 0;
  std::uint8_t doing = 0;
  std::uint8_t goal = 0;
  int counter = -1;
  int seat = -1;
  moved_state moved;
  /// placed_heading_rad, and the look's height_m and girth_m.
  std::array<std::uint64_t, 3> bits{};
  world::rgb8 shirt;
  world::rgb8 trousers;
  world::rgb8 skin;
  world::rgb8 hair;
  std::uint64_t queue_join_tick = 0;
  int route = -1;
  std::uint32_t goal_serial = 0;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, wire_pedestrian& x) {
  return f(x.id, x.doing, x.goal, x.counter, x.seat, x.moved, x.bits, x.shirt, x.trousers, x.skin,
           x.hair, x.queue_join_tick, x.route, x.goal_serial);
}

/// What became of each pedestrian of the new snapshot, in its (id) order.
enum class pedestrian_change : std::uint8_t {
  kept = 0,     ///< as before, bit for bit
  moved = 1,    ///< as before but its `moved_state`
  changed = 2,  ///< someone from before, sent whole
  arrived = 3,  ///< not in the snapshot before, sent whole
};

struct snapshot_delta {
  std::uint64_t tick = 0;
  /// The snapshot's time in seconds, as bits.
  std::uint64_t time_bits = 0;
  /// One byte per pedestrian of the snapshot before: 1 when it is not in this one. Its size
  /// also says which snapshot the delta applies to, so a receiver out of step finds out.
  std::vector<std::uint8_t> gone;
  /// One `pedestrian_change` per pedestrian of this snapshot. Bytes, which CAF copies as a
  /// block rather than element by element.
  std::vector<std::uint8_t> changes;
  std::vector<moved_state> moved;
  std::vector<wire_pedestrian> whole;
  std::vector<world::event> events;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, snapshot_delta& x) {
  return f(x.tick, x.time_bits, x.gone, x.changes, x.moved, x.whole, x.events);
}

/// A delta as CAF's binary serializer writes it, written once for every worker: the middleman
/// would write the same delta again for each (about 5 ms for the large station's), and a block
/// of bytes it only copies.
struct serialized_delta {
  std::vector<char> bytes;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, serialized_delta& x) {
  return f(x.bytes);
}

serialized_delta serialize(snapshot_delta& delta);

/// Throws std::invalid_argument when `bytes` is not a delta.
snapshot_delta deserialize(const serialized_delta& bytes);

/// `now` as changes to `before` (null: to an empty world, so the delta holds everyone). Both
/// hold their pedestrians in id order, as every snapshot does.
snapshot_delta delta_between(const world::snapshot* before, const world::snapshot& now);

/// The snapshot `delta` describes, rebuilt on `where` from `before` (null for an empty world).
/// Throws std::invalid_argument when the delta was not made from `before`.
std::shared_ptr<const world::snapshot> apply_delta(const world::station& where,
                                                   const world::snapshot* before,
                                                   snapshot_delta delta);

}  // namespace argus::actors
