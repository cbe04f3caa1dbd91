#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "actors/snapshot_delta.hpp"
#include "caf/allowed_unsafe_message_type.hpp"
#include "world/partition.hpp"
#include "world/pedestrian.hpp"
#include "world/snapshot.hpp"

namespace argus::actors {

/// What the world coordinator sends each crowd partition after a tick: the new snapshot, which
/// every partition reads (shared, never copied), and the pedestrians the partition steps next
/// tick — its own that stayed in its strip, then those handed over to it (by partition of
/// origin, each in id order), then newcomers, the order of `world::crowd::step`.
struct world_update {
  std::shared_ptr<const world::snapshot> snapshot;
  std::vector<world::pedestrian> pedestrians;
};

/// What a crowd partition sends the coordinator after stepping: its index and its result. From
/// a partition on a worker, the pedestrians it kept come as `kept`, changes to the snapshot it
/// stepped from, which the coordinator reads into `result.pedestrians` (states only) before
/// its step.
struct partition_report {
  std::size_t index = 0;
  world::partition_result result;
  std::optional<subset_delta> kept;
  /// A checkpoint from a partition on a worker (`partition_states::whole`).
  std::optional<std::vector<world::pedestrian>> whole;
};

}  // namespace argus::actors

// Heavy payloads that never leave the process: a snapshot holds every pedestrian and a
// neighbour index (shared by pointer precisely so it is not copied), and a partition's
// pedestrians carry private minds and RNGs that have no business on a wire. Local mail moves
// them without serialization, so they are allowed unsafe rather than given an inspect().
CAF_ALLOW_UNSAFE_MESSAGE_TYPE(argus::actors::world_update)
CAF_ALLOW_UNSAFE_MESSAGE_TYPE(argus::actors::partition_report)
