#pragma once

// A snapshot as it crosses to the workers (docs/distributed.md): what changed since the one
// before it. The whole crowd as CAF serialises it cost about 11 ms a side for 10,000 people
// (one call per field, 33 fields a person), every tick, on the run's critical path; most people
// only moved, and a seated or queueing one did not even do that. The receiver rebuilds the same
// pedestrians, bit for bit, and the same snapshot from them.

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "actors/wire_block.hpp"
#include "actors/wire_world.hpp"
#include "world/pedestrian.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::actors {

/// The fields a step changes in a walker, as bits (compared and sent as such, wire_double.hpp):
/// position, velocity and facing (x, y each), distance to the goal, squeeze. Everything else stays
/// as it was. A delta's vector of them crosses as one block of bytes (wire_block.hpp).
struct moved_state {
  std::array<std::uint64_t, 8> bits{};
  friend bool operator==(const moved_state&, const moved_state&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, moved_state& x) {
  return f(x.bits);
}

/// What became of each pedestrian of the new snapshot, in its (id) order.
enum class pedestrian_change : std::uint8_t {
  kept = 0,     ///< as before, bit for bit
  moved = 1,    ///< as before but its `moved_state`
  changed = 2,  ///< someone from before, sent whole
  arrived = 3,  ///< not in the snapshot before, sent whole
};

/// Some of a snapshot's pedestrians as they are a tick later, as changes to their records in it:
/// a crowd partition's own on a worker (wire_partition.hpp), which were all in the snapshot it
/// stepped from. One byte per pedestrian of that snapshot: a `pedestrian_change` (`kept`,
/// `moved`, `changed`), or `absent` when it is not one of them. Like a snapshot's delta, a
/// tenth of what the states themselves cost CAF to write and read.
struct subset_delta {
  static constexpr std::uint8_t absent = 0xff;
  std::vector<std::uint8_t> changes;
  std::vector<moved_state> moved;
  std::vector<world::pedestrian_state> whole;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, subset_delta& x) {
  return f(x.changes, as_block(x.moved), x.whole);
}

struct snapshot_delta {
  std::uint64_t tick = 0;
  double time_s = 0.0;
  /// One byte per pedestrian of the snapshot before: 1 when it is not in this one. Its size
  /// also says which snapshot the delta applies to, so a receiver out of step finds out.
  std::vector<std::uint8_t> gone;
  /// One `pedestrian_change` per pedestrian of this snapshot. Bytes, which CAF copies as a
  /// block rather than element by element.
  std::vector<std::uint8_t> changes;
  std::vector<moved_state> moved;
  std::vector<world::pedestrian_state> whole;
  std::vector<world::event> events;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, snapshot_delta& x) {
  return f(x.tick, as_bits(x.time_s), x.gone, x.changes, as_block(x.moved), x.whole, x.events);
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

/// `now` (in id order, each in `before`) as changes to `before`. Throws std::invalid_argument
/// naming a pedestrian that is not in `before` or out of order.
subset_delta subset_between(const world::snapshot& before, std::span<const world::pedestrian> now);

/// The states each of `deltas` describes, in id order, read in one pass over `before`. Throws
/// std::invalid_argument when one was not made from `before`.
std::vector<std::vector<world::pedestrian_state>> apply_subsets(const world::snapshot& before,
                                                                std::vector<subset_delta> deltas);

/// The snapshot `delta` describes, rebuilt on `where` from `before` (null for an empty world).
/// Throws std::invalid_argument when the delta was not made from `before`.
std::shared_ptr<const world::snapshot> apply_delta(const world::station& where,
                                                   const world::snapshot* before,
                                                   snapshot_delta delta);

}  // namespace argus::actors
