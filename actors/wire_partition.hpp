#pragma once

// What crosses between the world coordinator and a crowd partition that steps on a worker
// (docs/distributed.md, "The crowd on the workers"). A partition there keeps its own
// pedestrians from tick to tick and reads the snapshot from its worker's board, so only
// hand-overs, newcomers and what the snapshot needs travel. Inspectors and type IDs
// (actors/type_ids.hpp) let the middleman carry them; doubles cross as their bits.

#include <cstdint>
#include <vector>

#include "actors/snapshot_delta.hpp"
#include "actors/wire_double.hpp"
#include "actors/wire_world.hpp"
#include "world/event.hpp"
#include "world/pedestrian.hpp"

namespace argus::actors {

/// A crowd partition a worker spawns: its index, its strip (`world::partition_bounds`) and the
/// pedestrians it owns in the snapshot of tick 0.
struct partition_placement {
  std::uint64_t index = 0;
  double min_x_m = 0.0;
  double max_x_m = 0.0;
  std::vector<world::pedestrian> pedestrians;
  /// Under `--on-worker-loss crash-nodes`: it sends its pedestrians whole every
  /// `partition_checkpoint_ticks` (actors/partition_shadow.hpp), so the coordinator can step it
  /// on if the worker is lost.
  bool checkpoints = false;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, partition_placement& x) {
  return f(x.index, as_bits(x.min_x_m), as_bits(x.max_x_m), x.pedestrians, x.checkpoints);
}

/// What the coordinator sends a partition on a worker after each tick: the pedestrians handed
/// over to it (by partition of origin, each in id order), then its newcomers. It steps them
/// after its own, as `world::crowd::step` does.
struct partition_arrivals {
  std::vector<world::pedestrian> pedestrians;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, partition_arrivals& x) {
  return f(x.pedestrians);
}

/// What a partition on a worker reports after stepping: the public states of its own that
/// stayed in its strip (their minds stay with it), as changes to the snapshot it stepped from;
/// whole those that crossed out; and the tick's events.
struct partition_states {
  std::uint64_t index = 0;
  subset_delta kept;
  std::vector<world::pedestrian> handed_over;
  std::vector<world::event> events;
  /// A checkpoint (`partition_placement::checkpoints`): `whole` holds the pedestrians it kept,
  /// minds and generators included, in the order it steps them.
  bool checkpoint = false;
  std::vector<world::pedestrian> whole;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, partition_states& x) {
  return f(x.index, x.kept, x.handed_over, x.events, x.checkpoint, x.whole);
}

}  // namespace argus::actors
