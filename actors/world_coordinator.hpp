#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "actors/operator_board.hpp"
#include "actors/participant_info.hpp"
#include "actors/snapshot_board.hpp"
#include "actors/wire_live.hpp"
#include "actors/worker_loss.hpp"
#include "actors/worker_protocol.hpp"
#include "caf/actor.hpp"
#include "caf/fwd.hpp"
#include "eval/observation_log.hpp"
#include "eval/records.hpp"
#include "world/crowd.hpp"
#include "world/station.hpp"

namespace argus::actors {

/// How the world coordinator takes part in the clock: phase network, on demand (woken by the
/// partitions' reports, so it runs in the same tick, right after them).
participant_info world_coordinator_participant();

/// A worker that steps a crowd partition (docs/distributed.md, "The crowd on the workers").
struct partition_host {
  /// Its host (spawn_worker_host); null: the partition steps here.
  caf::actor host;
  /// Its name (HOST:PORT), which the partition's participant carries, so the worker ticks it.
  std::string name;
};

/// What the world of a run needs.
struct world_run_settings {
  std::shared_ptr<const world::station> station;
  world::crowd_settings crowd;
  /// The clock's last tick + 1: the snapshot of this world tick ends the run.
  std::int64_t end_tick = 0;
  /// Where to write the ground-truth trajectories (CSV, world::trajectory_writer); empty for
  /// none. Written as `<file>.partial` and renamed once the last tick is written.
  std::filesystem::path trajectories;
  /// Participants (handle, participant id) that receive every new snapshot as
  /// `(world_snapshot_atom, mail_stamp, std::shared_ptr<const world::snapshot>)`, stamped in
  /// phase network, so an observer of phase cameras reads it in the same tick (the video
  /// recorder).
  std::vector<std::pair<caf::actor, std::uint64_t>> snapshot_observers;
  /// Where camera nodes read the latest snapshot (snapshot_board.hpp); null for none.
  std::shared_ptr<snapshot_board> board;
  /// A distributed run's workers (actors/worker_host.hpp), whose cameras read boards of their
  /// own. Before each publication the coordinator takes the picks their cameras made (from
  /// their answers in phase world, which the clock passes on as `(gather_atom, actor_addr,
  /// int64 tick, worker_gather)`; a worker with nothing to tick in phase world is asked,
  /// `gather_atom`) and hands them to `picks_gathered`, so the local board's subscribers see
  /// them as in one process; after it, it sends every worker the snapshot and every pick
  /// (`board_atom`), and acknowledges its tick at once: a worker reads them before its next
  /// batch from the clock, which comes over the same connection after them. A worker's answer
  /// is acted on only when it is a failure.
  std::vector<caf::actor> remote_boards;
  std::function<void(const std::vector<eval::task_origin>&)> picks_gathered;
  /// The workers' cameras' poses, gathered with their picks when the run records video; null
  /// for none.
  std::function<void(const std::vector<pose_record>&)> poses_gathered;
  /// What the workers' cameras recorded since the last gather (`worker_setup::stream_log`),
  /// one worker's share at a time, in the workers' order; null when the logs come at the end.
  std::function<void(eval::observation_log::contents)> log_gathered;
  /// A lost worker under `worker_loss::crash_nodes`: the world goes on with the others.
  worker_loss on_worker_loss = worker_loss::end_run;
  /// Where each crowd partition steps, by index (`placement.crowd: workers`); empty, or a
  /// null host, for here. A worker's partition is spawned there (`spawn_partition_atom`).
  std::vector<partition_host> partition_hosts;
  /// A live run across workers (`argus serve --workers`): the operator's orders published here
  /// go out to every worker with the next snapshot (`operator_orders_atom`, before `board_atom`,
  /// so the workers' cameras read them in the same tick as one process's); null for none.
  std::shared_ptr<const operator_board> operators;
  /// What the console shows of the workers' cameras, gathered with their picks, one worker's at
  /// a time; null for none.
  std::function<void(live_display)> display_gathered;
  /// The cameras a page watches (`live::console_state::watched`), read before each publication:
  /// when they change, every worker is told (`display_watch_atom`), and sends only their frames.
  /// Null for none.
  std::function<std::vector<int>()> watched_cameras;
  /// How many threads step a lost worker's partitions here, side by side (crash-nodes); 0 for
  /// one per core.
  std::size_t adopted_threads = 0;
};

/// The actors of a run's crowd, to join to the clock.
struct world_actors {
  std::vector<std::pair<caf::actor, participant_info>> participants;
};

/// Spawns the crowd of a run: one crowd-partition actor per vertical strip
/// (`world::vertical_strips`) and the world coordinator, starting from the same initial crowd
/// as `world::crowd` (same spawner, same prefill), so that the run reproduces
/// `world::crowd::step` tick for tick, bit for bit, for any partition and thread count.
///
/// Clock tick t runs world tick t + 1: in phase world every partition steps its pedestrians
/// from the snapshot of world tick t and reports `(world_report_atom, mail_stamp,
/// partition_report)` to the coordinator. In phase network the coordinator takes the reports
/// in partition order, runs the spawner on the gathered states, merges the immutable snapshot
/// of world tick t + 1, appends it to the trajectories, emits `pedestrian_entered`,
/// `pedestrian_left` and `goal_completed` events, and sends every partition
/// `(world_update_atom, mail_stamp, world_update)`: the shared snapshot and the pedestrians it
/// owns now (hand-overs and newcomers go to `world::owner_of` their position).
///
/// The attachments (`(world_attach_atom, actor)` to each partition) are sent from the calling
/// thread, so they precede any tick when the caller joins the actors before `start`.
///
/// A partition placed on a worker (`settings.partition_hosts`) is spawned there, from the
/// calling thread, before any here; throws std::runtime_error naming the worker that refuses
/// or does not answer, having ended nothing (the caller ends the run's other actors).
world_actors spawn_world(caf::actor_system& system, world_run_settings settings);

}  // namespace argus::actors
