#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "world/behaviour.hpp"
#include "world/partition.hpp"
#include "world/pedestrian.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::actors {

/// Every how many ticks a crowd partition on a worker sends its pedestrians whole under
/// `--on-worker-loss crash-nodes` (docs/distributed.md, "A lost worker"): partition `i` at the
/// ticks t with (t + i) % partition_checkpoint_ticks == 0, so the partitions take turns. One
/// second of a 15 Hz run: a checkpoint then costs about a fifteenth of the crowd's minds a tick,
/// and a loss is made good by at most fifteen steps of one partition.
inline constexpr std::int64_t partition_checkpoint_ticks = 15;

/// Whether crowd partition `index` sends its pedestrians whole after its step of `tick`.
constexpr bool is_checkpoint_tick(std::int64_t tick, std::size_t index) noexcept {
  return (tick + static_cast<std::int64_t>(index)) % partition_checkpoint_ticks == 0;
}

/// What the world coordinator keeps of a crowd partition that steps on a worker, so that it
/// can step the partition itself, from the very state the worker held, once that worker is
/// lost (`--on-worker-loss crash-nodes`).
///
/// The coordinator sees only the public states of the pedestrians a worker's partition keeps;
/// their minds and generators stay there. A partition's step is a pure function of the
/// snapshot it steps from and of its pedestrians (`world::partition_step`), and its
/// pedestrians at the start of a tick are those it kept, then those the coordinator sent it
/// (hand-overs, newcomers). So the coordinator keeps the pedestrians as of the partition's last
/// checkpoint (sent whole), then, for every tick since, the snapshot it stepped from and what
/// it was sent after: stepping those ticks again gives its pedestrians bit for bit.
///
///   checkpoint at tick c        tick c+1               tick c+2
///   start = kept_c + sent_c --> step(S_{c+1}) + sent_{c+1} --> step(S_{c+2}) + sent_{c+2} --> ...
class partition_shadow {
 public:
  /// A partition whose pedestrians at the start of its first tick are `start`.
  explicit partition_shadow(std::vector<world::pedestrian> start) : start_(std::move(start)) {}

  /// The partition stepped from `previous` and was then sent `arrivals`. `whole`, when not
  /// null, is the checkpoint it sent with that step: the pedestrians it kept, whole.
  void stepped(std::shared_ptr<const world::snapshot> previous,
               std::vector<world::pedestrian>* whole, std::vector<world::pedestrian> arrivals);

  /// The partition's pedestrians at the start of its next tick, stepped again here from its
  /// last checkpoint.
  std::vector<world::pedestrian> replay(const world::station& where,
                                        const world::partition_bounds& bounds,
                                        const world::behaviour_settings& behaviour) const;

  /// How many ticks `replay` steps again.
  std::size_t ticks_since_checkpoint() const noexcept { return since_.size(); }

 private:
  struct step_input {
    std::shared_ptr<const world::snapshot> previous;
    std::vector<world::pedestrian> arrivals;
  };
  std::vector<world::pedestrian> start_;
  std::vector<step_input> since_;
};

}  // namespace argus::actors
