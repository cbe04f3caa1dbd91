#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>

#include "caf/fwd.hpp"

namespace argus::world {
class snapshot;
}

namespace argus::actors {

/// `trajectories.csv` and, beside it, `pedestrians.csv` (who looks like what), each written as
/// `<name>.partial` and given its name once complete, so an interrupted run leaves nothing that
/// looks whole.
struct trajectory_file;

/// Opens both files; throws naming the one that cannot be written. Empty path: null, none.
std::shared_ptr<trajectory_file> open_trajectories(const std::filesystem::path& path);

/// Appends `frame`'s rows; once `frame` is the snapshot of `end_tick`, both files get their
/// names and `file` is released.
void write_trajectories(std::shared_ptr<trajectory_file>& file, const world::snapshot& frame,
                        std::int64_t end_tick);

/// Spawns the actor that writes `file` from the world's snapshots, on a thread of its own
/// (docs/world.md, "The crowd as actors"), linked to `owner`, the world coordinator.
///
/// It exists so that the rows are never on the clock's path. Written by the world coordinator
/// after it acknowledged a tick, they still delayed the tick: the acknowledgement makes the
/// clock ready on the coordinator's own scheduler thread, which ran the rows first (about 5 ms
/// a tick for 10,000 pedestrians) while the other core waited, in a distributed run the
/// workers too.
///
/// Messages: `(world_snapshot_atom, std::shared_ptr<const world::snapshot>)` appends its rows
/// and answers `(recorded_atom, int64 tick)`; snapshots are written in the order they come.
/// When `owner` ends, for any reason, what it sent before is written, the files get their
/// names, and this actor ends too.
caf::actor spawn_trajectory_recorder(caf::local_actor* owner, std::shared_ptr<trajectory_file> file,
                                     std::int64_t end_tick);

}  // namespace argus::actors
