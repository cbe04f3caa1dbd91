#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "actors/worker_loss.hpp"
#include "config/scenario.hpp"

namespace argus::actors {

/// Which worker (0 .. workers - 1) hosts each camera, by camera id: every worker gets
/// `cameras / workers` cameras or one more, the first workers the extra ones. Throws
/// std::invalid_argument when there are more workers than cameras.
/// `scenario.placement.policy` says how (docs/distributed.md, "Placement").
std::map<int, std::size_t> place_cameras(const config::scenario& scenario, std::size_t workers);

/// Which worker steps each crowd partition, by index (`scenario.world.partitions` strips, west
/// to east), none for the coordinator: with `placement.crowd: workers`, consecutive strips in
/// blocks, worker w taking partitions i with i * workers / partitions == w (fewer partitions
/// than workers leave the last workers without); all on the coordinator with
/// `placement.crowd: coordinator`. Under `--on-worker-loss crash-nodes` the coordinator steps a
/// lost worker's partitions on from their checkpoints (actors/partition_shadow.hpp).
std::vector<std::optional<std::size_t>> place_partitions(const config::scenario& scenario,
                                                         std::size_t workers);

/// Which worker hosts the link between cameras `a` and `b`: camera `a`'s, or none (the
/// coordinator) when the run survives lost workers and `b` is on another worker. A link must
/// outlive each camera whose hand-overs it owes: a lost worker then takes with it only links
/// whose two ends it also took (docs/distributed.md, "A lost worker").
inline std::optional<std::size_t> place_link(const std::map<int, std::size_t>& cameras, int a,
                                             int b, worker_loss on_loss) {
  const auto worker = cameras.at(a);
  if (on_loss == worker_loss::crash_nodes && cameras.at(b) != worker) return std::nullopt;
  return worker;
}

}  // namespace argus::actors
