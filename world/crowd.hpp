#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "config/scenario.hpp"
#include "world/behaviour.hpp"
#include "world/partition.hpp"
#include "world/snapshot.hpp"
#include "world/spawner.hpp"
#include "world/station.hpp"

namespace argus::world {

/// Everything a crowd needs besides the station.
struct crowd_settings {
  std::uint64_t run_seed = 1;
  unsigned population = 100;
  double spawn_rate_per_min = 60.0;
  unsigned partitions = 1;
  /// Start with the target population already in the station (see spawner::populate).
  bool prefill = true;
  behaviour_settings behaviour;
  /// Where preferred speeds come from.
  speed_distribution speeds;
  /// How clothes are coloured.
  config::clothing clothes = config::clothing::palette;
  /// Streams of pedestrians to an exit (standard experiments).
  std::vector<flow> flows;
  /// The scenario file the flows came from, for problems.
  std::string source_path;

  /// The crowd a scenario asks for (seed, tick, world settings, speeds, flows).
  static crowd_settings from(const config::scenario& scenario);

  /// The spawner's settings, with each flow's exit resolved against `where`'s portals;
  /// throws config::scenario_error naming the flow when its exit is no portal of the layout.
  spawner_settings spawning(const station& where) const;
};

/// The whole crowd stepped in one thread: the reference sequence that the crowd-partition
/// actors reproduce. One tick:
///
/// 1. every partition runs partition_step on its own pedestrians against the shared
///    previous snapshot (phase one: compute);
/// 2. the spawner places newcomers given everyone's new state (gather_states);
/// 3. merge builds the next immutable snapshot (phase two: apply), and handed-over and new
///    pedestrians move to the partition owning their position.
class crowd {
 public:
  /// Builds the partitions and, with `prefill`, the initial crowd (snapshot of tick 0).
  crowd(std::shared_ptr<const station> where, crowd_settings settings);

  /// Advances one tick.
  void step();

  /// The latest snapshot (tick 0 before the first step).
  const std::shared_ptr<const snapshot>& current() const noexcept { return current_; }

  /// The station.
  const station& where() const noexcept { return *station_; }

  /// The partitions' strips.
  std::span<const partition_bounds> bounds() const noexcept { return bounds_; }

  /// The pedestrians each partition owns now.
  std::span<const std::vector<pedestrian>> owned() const noexcept { return owned_; }

  /// Pedestrians handed from one partition to another in the last step.
  std::size_t last_hand_overs() const noexcept { return last_hand_overs_; }

 private:
  std::shared_ptr<const station> station_;
  crowd_settings settings_;
  spawner spawner_;
  std::vector<partition_bounds> bounds_;
  std::vector<std::vector<pedestrian>> owned_;
  std::shared_ptr<const snapshot> current_;
  std::size_t last_hand_overs_ = 0;
};

}  // namespace argus::world
