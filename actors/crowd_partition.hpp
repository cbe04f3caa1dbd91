#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "actors/participant_info.hpp"
#include "actors/snapshot_board.hpp"
#include "caf/fwd.hpp"
#include "world/behaviour.hpp"
#include "world/partition.hpp"
#include "world/pedestrian.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::actors {

/// How crowd partition number `index` takes part in the clock: phase world, every tick.
participant_info crowd_partition_participant(std::size_t index);

/// What a crowd partition starts with.
struct crowd_partition_setup {
  std::size_t index = 0;
  std::shared_ptr<const world::station> station;
  world::partition_bounds bounds;
  world::behaviour_settings behaviour;
  /// The snapshot of tick 0 and the pedestrians of this strip in it.
  std::shared_ptr<const world::snapshot> initial;
  std::vector<world::pedestrian> pedestrians;
  /// Set on a worker (docs/distributed.md, "The crowd on the workers"): the worker's board,
  /// where the partition reads each tick's snapshot (`initial` is then null). Such a partition
  /// keeps its own pedestrians, reports `partition_states` and is sent `partition_arrivals`.
  std::shared_ptr<snapshot_board> board;
  /// On a worker under `--on-worker-loss crash-nodes`: it sends its pedestrians whole at its
  /// checkpoint ticks (actors/partition_shadow.hpp).
  bool checkpoints = false;
};

/// Spawns the actor of one crowd partition (docs/world.md, "Stepping, partitions, spawning").
///
/// At clock tick t it steps its pedestrians with `world::partition_step` from the snapshot of
/// world tick t (the end of clock tick t - 1) and sends
/// `(world_report_atom, mail_stamp, partition_report)` to the coordinator, which answers
/// before the partition's next tick with `(world_update_atom, mail_stamp, world_update)`:
/// the snapshot of world tick t + 1 and the pedestrians it steps next (its own, hand-overs,
/// newcomers). The coordinator's handle comes first, as `(world_attach_atom, actor)`.
///
/// On a worker (`setup.board` set) the same tick crosses less: the snapshot is the board's
/// (rebuilt there from the world's delta before the tick), the report is
/// `(world_report_atom, mail_stamp, partition_states)` and the answer
/// `(world_update_atom, mail_stamp, partition_arrivals)`, stepped after the pedestrians it kept.
caf::actor spawn_crowd_partition(caf::actor_system& system, crowd_partition_setup setup);

}  // namespace argus::actors
