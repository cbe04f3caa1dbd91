#include "world/partition.hpp"

#include <algorithm>

#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::world {

std::vector<partition_bounds> vertical_strips(const station& where, unsigned count) {
  count = std::max(count, 1u);
  std::vector<partition_bounds> strips(count);
  const double width = where.plan().size_m.x() / count;
  for (unsigned i = 1; i < count; ++i) {
    strips[i - 1].max_x_m = width * i;
    strips[i].min_x_m = width * i;
  }
  return strips;
}

std::size_t owner_of(std::span<const partition_bounds> strips, const vec2& p) {
  for (std::size_t i = 0; i < strips.size(); ++i) {
    if (strips[i].contains(p)) return i;
  }
  return strips.empty() ? 0 : strips.size() - 1;  // NaN positions: the last strip
}

partition_result partition_step(const station& where, const snapshot& previous,
                                std::span<const pedestrian> own, const partition_bounds& bounds,
                                const behaviour_settings& settings) {
  partition_result out;
  out.pedestrians.reserve(own.size());
  for (std::size_t i = 0; i < own.size(); ++i) {
    const auto& each = own[i];
    if (i + 1 < own.size()) where.prefetch_route(own[i + 1].field, own[i + 1].state.position);
    auto next = step_pedestrian(where, previous, each, settings, out.events);
    if (!next) continue;
    (bounds.contains(next->state.position) ? out.pedestrians : out.handed_over)
        .push_back(std::move(*next));
  }
  // Stepped in the order owned, which is id order but for those handed over last tick: check
  // (linear) before sorting (not).
  auto by_id = [](const pedestrian& a, const pedestrian& b) { return a.state.id < b.state.id; };
  for (auto* list : {&out.pedestrians, &out.handed_over}) {
    if (!std::is_sorted(list->begin(), list->end(), by_id)) {
      std::sort(list->begin(), list->end(), by_id);
    }
  }
  return out;
}

std::vector<pedestrian_state> gather_states(std::span<const partition_result> results) {
  std::vector<pedestrian_state> states;
  std::size_t total = 0;
  for (const auto& r : results) total += r.pedestrians.size() + r.handed_over.size();
  states.reserve(total);
  for (const auto& r : results) {
    for (const auto& p : r.pedestrians) states.push_back(p.state);
    for (const auto& p : r.handed_over) states.push_back(p.state);
  }
  return states;
}

std::shared_ptr<const snapshot> merge(const station& where, std::uint64_t tick,
                                      std::chrono::duration<double> time,
                                      std::vector<pedestrian_state> gathered,
                                      std::span<const partition_result> results,
                                      std::span<const pedestrian> spawned,
                                      std::vector<event> spawn_events) {
  auto states = std::move(gathered);
  for (const auto& p : spawned) states.push_back(p.state);
  std::vector<event> events;
  for (const auto& r : results) events.insert(events.end(), r.events.begin(), r.events.end());
  events.insert(events.end(), spawn_events.begin(), spawn_events.end());
  return std::make_shared<const snapshot>(where, tick, time, std::move(states), std::move(events));
}

}  // namespace argus::world
