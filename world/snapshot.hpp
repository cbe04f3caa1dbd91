#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "world/event.hpp"
#include "world/neighbour.hpp"
#include "world/neighbour_sieve.hpp"
#include "world/pedestrian.hpp"

namespace argus::world {

class station;

/// The world at the end of one tick, immutable once built and shared by every reader
/// (`std::shared_ptr<const snapshot>`): every pedestrian's public state in id order, a
/// uniform-grid index for neighbour queries, the ticket/vending lines in service order and
/// the seat claims, and the tick's events. Everything a pedestrian decides in the next tick
/// is decided from this object only, which makes the result independent of stepping order
/// and of the partitioning (paper Section II's crowd, stepped as RVO2 does).
class snapshot {
 public:
  /// Grid cell size of the neighbour index; no interaction reaches farther.
  static constexpr double neighbour_cell_m = 2.0;

  /// Builds the indices; `pedestrians` need not be sorted, `events` are sorted stably by
  /// pedestrian id.
  snapshot(const station& where, std::uint64_t tick, std::chrono::duration<double> time,
           std::vector<pedestrian_state> pedestrians, std::vector<event> events = {});

  /// The tick this snapshot ends (0 = initial state).
  std::uint64_t tick() const noexcept { return tick_; }
  /// Virtual time at the end of the tick.
  std::chrono::duration<double> time() const noexcept { return time_; }

  /// Every pedestrian, sorted by id.
  std::span<const pedestrian_state> pedestrians() const noexcept { return pedestrians_; }
  /// The pedestrian with `id`, or nullptr.
  const pedestrian_state* find(int id) const;
  /// Events of this tick, by pedestrian id.
  std::span<const event> events() const noexcept { return events_; }

  /// Calls `visit(const neighbour&)` for every pedestrian in the 3 x 3 index cells
  /// around `p` (a superset of those within neighbour_cell_m), in an order that depends only
  /// on the snapshot's content.
  template <class Visitor>
  void for_each_near(const vec2& p, Visitor&& visit) const {
    for_each_row_near(p, [&](std::uint32_t begin, std::uint32_t end) {
      for (std::uint32_t k = begin; k < end; ++k) visit(neighbours_[k]);
    });
  }

  /// Calls `visit(const neighbour&)` for those of for_each_near's cells whom `sieve` keeps,
  /// in the same order: `sieve.sift(columns(), begin, end, picked)` writes the kept indices of
  /// [begin, end) to `picked` and returns how many (neighbour_sieve). Sifting the columns
  /// first, the visit reads the records of only those kept (in a packed station, a third of
  /// the 3 x 3 cells' people).
  template <class Sieve, class Visitor>
  void for_each_sifted(const vec2& p, const Sieve& sieve, Visitor&& visit) const {
    constexpr std::uint32_t chunk = 128;
    std::array<std::uint32_t, chunk> picked;
    const neighbour_columns c = columns();
    for_each_row_near(p, [&](std::uint32_t k, std::uint32_t end) {
      for (; k < end; k += chunk) {
        const std::size_t count = sieve.sift(c, k, std::min(end, k + chunk), picked.data());
        for (std::size_t i = 0; i < count; ++i) visit(neighbours_[picked[i]]);
      }
    });
  }

  /// The neighbour index's people as columns, in the index's order.
  neighbour_columns columns() const noexcept {
    return {x_.data(), y_.data(), vx_.data(), vy_.data(), radius_.data()};
  }

  /// Number of pedestrians in counter `counter`'s line (walking to it, waiting or served).
  std::size_t queue_length(int counter) const { return queues_[counter].size(); }
  /// Place in line of a pedestrian who joined counter `counter` at `join_tick`: the number
  /// of pedestrians ahead of it, ordered by (join tick, id).
  std::size_t queue_rank(int counter, std::uint64_t join_tick, int id) const;
  /// The line of counter `counter` in service order: (join tick, id) pairs.
  std::span<const std::pair<std::uint64_t, int>> queue(int counter) const {
    return queues_[counter];
  }
  /// The pedestrian with the lowest id claiming seat `seat`, or -1: the seat is theirs.
  int seat_holder(int seat) const { return seat_holder_[seat]; }

 private:
  /// Calls `rows(begin, end)` with the index range of each row of the 3 x 3 cells around `p`
  /// (a row's three cells are adjacent in the index), in increasing y.
  template <class Rows>
  void for_each_row_near(const vec2& p, Rows&& rows) const {
    const int cx = cell_x(p.x());
    const int cy = cell_y(p.y());
    const int x0 = std::max(0, cx - 1);
    const int x1 = std::min(grid_w_ - 1, cx + 1);
    for (int y = std::max(0, cy - 1); y <= std::min(grid_h_ - 1, cy + 1); ++y) {
      const int row = y * grid_w_;
      rows(cell_start_[row + x0], cell_start_[row + x1 + 1]);
    }
  }

  int cell_x(double x) const {
    return std::clamp(static_cast<int>(x / neighbour_cell_m), 0, grid_w_ - 1);
  }
  int cell_y(double y) const {
    return std::clamp(static_cast<int>(y / neighbour_cell_m), 0, grid_h_ - 1);
  }

  std::uint64_t tick_ = 0;
  std::chrono::duration<double> time_{0.0};
  std::vector<pedestrian_state> pedestrians_;
  std::vector<event> events_;
  int grid_w_ = 1;
  int grid_h_ = 1;
  // CSR neighbour index: cell c holds neighbours_[cell_start_[c] .. cell_start_[c + 1]), in id
  // order; a row's cells are contiguous, so one range spans three cells.
  std::vector<std::uint32_t> cell_start_;
  std::vector<neighbour> neighbours_;
  // neighbours_' positions, velocities and radii as columns (for_each_sifted).
  std::vector<double> x_, y_, vx_, vy_, radius_;
  std::vector<std::vector<std::pair<std::uint64_t, int>>> queues_;
  std::vector<int> seat_holder_;
};

}  // namespace argus::world
