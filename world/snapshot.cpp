#include "world/snapshot.hpp"

#include <algorithm>
#include <cmath>

#include "world/station.hpp"

namespace argus::world {

snapshot::snapshot(const station& where, std::uint64_t tick, std::chrono::duration<double> time,
                   std::vector<pedestrian_state> pedestrians, std::vector<event> events)
    : tick_(tick), time_(time), pedestrians_(std::move(pedestrians)), events_(std::move(events)) {
  // The crowd hands them over in id order already (partitions step in id order, newcomers
  // get new ids): checking is linear, sorting would not be.
  const auto by_id = [](const pedestrian_state& a, const pedestrian_state& b) {
    return a.id < b.id;
  };
  if (!std::is_sorted(pedestrians_.begin(), pedestrians_.end(), by_id)) {
    std::sort(pedestrians_.begin(), pedestrians_.end(), by_id);
  }
  std::stable_sort(events_.begin(), events_.end(),
                   [](const event& a, const event& b) { return a.pedestrian < b.pedestrian; });
  const vec2 size = where.plan().size_m;
  grid_w_ = std::max(1, static_cast<int>(std::ceil(size.x() / neighbour_cell_m)));
  grid_h_ = std::max(1, static_cast<int>(std::ceil(size.y() / neighbour_cell_m)));
  // Counting sort by cell, keeping id order within each cell: counts, their running sums
  // (each cell's end), then everyone placed from the back, each cell's end counting down to
  // its start. No copy of the starts to fill from: a small crowd in a large station pays
  // for the cells (5,000 in Penn Station's 200 x 100 m), not for its people.
  const auto cells = static_cast<std::size_t>(grid_w_) * grid_h_;
  cell_start_.assign(cells + 1, 0);
  std::vector<std::uint32_t> cell_of(pedestrians_.size());
  for (std::size_t i = 0; i < pedestrians_.size(); ++i) {
    const auto& p = pedestrians_[i].position;
    cell_of[i] = static_cast<std::uint32_t>(cell_y(p.y()) * grid_w_ + cell_x(p.x()));
    ++cell_start_[cell_of[i]];
  }
  for (std::size_t c = 1; c <= cells; ++c) cell_start_[c] += cell_start_[c - 1];
  neighbours_.resize(pedestrians_.size());
  for (auto* column : {&x_, &y_, &vx_, &vy_, &radius_}) column->resize(pedestrians_.size());
  for (std::size_t i = pedestrians_.size(); i-- > 0;) {
    const auto at = --cell_start_[cell_of[i]];
    const auto& placed = neighbours_[at] = neighbour(pedestrians_[i]);
    x_[at] = placed.position.x();
    y_[at] = placed.position.y();
    vx_[at] = placed.velocity.x();
    vy_[at] = placed.velocity.y();
    radius_[at] = placed.radius;
  }
  queues_.assign(where.counter_count(), {});
  seat_holder_.assign(where.seats().size(), -1);
  for (const auto& p : pedestrians_) {
    if (p.counter >= 0 && p.counter < static_cast<int>(queues_.size())) {
      queues_[p.counter].push_back({p.queue_join_tick, p.id});
    }
    // Ids ascend, so the first claimant is the lowest id.
    if (p.seat >= 0 && p.seat < static_cast<int>(seat_holder_.size()) && seat_holder_[p.seat] < 0) {
      seat_holder_[p.seat] = p.id;
    }
  }
  for (auto& line : queues_) std::sort(line.begin(), line.end());
}

const pedestrian_state* snapshot::find(int id) const {
  const auto it = std::lower_bound(pedestrians_.begin(), pedestrians_.end(), id,
                                   [](const pedestrian_state& p, int key) { return p.id < key; });
  return it != pedestrians_.end() && it->id == id ? &*it : nullptr;
}

std::size_t snapshot::queue_rank(int counter, std::uint64_t join_tick, int id) const {
  const auto& line = queues_[counter];
  return static_cast<std::size_t>(
      std::lower_bound(line.begin(), line.end(), std::pair<std::uint64_t, int>{join_tick, id}) -
      line.begin());
}

}  // namespace argus::world
