#pragma once

#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "world/behaviour.hpp"
#include "world/event.hpp"
#include "world/pedestrian.hpp"

namespace argus::world {

class snapshot;
class station;

/// A crowd partition's share of the floor: the vertical strip min_x_m <= x < max_x_m. The
/// outermost strips extend to infinity so every position has exactly one owner.
struct partition_bounds {
  double min_x_m = -std::numeric_limits<double>::infinity();
  double max_x_m = std::numeric_limits<double>::infinity();
  /// Whether `p` belongs to this strip.
  bool contains(const vec2& p) const noexcept { return p.x() >= min_x_m && p.x() < max_x_m; }
  friend bool operator==(const partition_bounds&, const partition_bounds&) = default;
};

/// Splits the station into `count` vertical strips of equal width (count >= 1).
std::vector<partition_bounds> vertical_strips(const station& where, unsigned count);

/// Index of the strip in `strips` that contains `p`.
std::size_t owner_of(std::span<const partition_bounds> strips, const vec2& p);

/// What one partition returns from a tick.
struct partition_result {
  /// Its pedestrians after the step that are still inside its strip, in id order.
  std::vector<pedestrian> pedestrians;
  /// Pedestrians that crossed out of its strip: they go to the partition that owns their new
  /// position (owner_of), which steps them from the next tick on.
  std::vector<pedestrian> handed_over;
  /// The tick's events of its pedestrians (including those that left the station).
  std::vector<event> events;
};

/// Steps the pedestrians a partition owns (`own`, which lie in `bounds` in `previous`) by one
/// tick. Each reads only `previous`, the full snapshot of the last tick — neighbours in other
/// strips included — so the union of all partitions' results does not depend on the
/// partitioning: bit-identical, since each pedestrian's arithmetic is the same sequence of
/// operations whichever partition runs it (neighbours are visited in snapshot order).
partition_result partition_step(const station& where, const snapshot& previous,
                                std::span<const pedestrian> own, const partition_bounds& bounds,
                                const behaviour_settings& settings);

/// Phase two: the next snapshot from every partition's result (pedestrians, handed-over
/// pedestrians and events) plus the pedestrians spawned this tick and the spawner's events.
/// `gathered` is gather_states(results), which the spawner has already needed: taken over
/// rather than copied again.
std::shared_ptr<const snapshot> merge(const station& where, std::uint64_t tick,
                                      std::chrono::duration<double> time,
                                      std::vector<pedestrian_state> gathered,
                                      std::span<const partition_result> results,
                                      std::span<const pedestrian> spawned,
                                      std::vector<event> spawn_events = {});

/// The public states of every pedestrian in `results` (kept and handed over), for the
/// spawner, which must see who stands where before placing newcomers.
std::vector<pedestrian_state> gather_states(std::span<const partition_result> results);

}  // namespace argus::world
