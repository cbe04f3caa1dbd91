#include "actors/worker_placement.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "fmt/format.h"

namespace argus::actors {

std::map<int, std::size_t> place_cameras(const config::scenario& scenario, std::size_t workers) {
  const auto& cameras = scenario.cameras;
  if (workers == 0) throw std::invalid_argument("a distributed run needs at least one worker");
  if (workers > cameras.size())
    throw std::invalid_argument(
        fmt::format("{} workers for {} cameras: every worker must host at least one camera",
                    workers, cameras.size()));
  std::vector<const config::camera_settings*> order;
  for (const auto& c : cameras) order.push_back(&c);
  if (scenario.placement.policy == config::placement_policy::region) {
    double min_x = 0.0, max_x = 0.0, min_y = 0.0, max_y = 0.0;
    for (std::size_t i = 0; i < order.size(); ++i) {
      const auto& p = order[i]->position;
      min_x = i == 0 ? p.x_m : std::min(min_x, p.x_m);
      max_x = i == 0 ? p.x_m : std::max(max_x, p.x_m);
      min_y = i == 0 ? p.y_m : std::min(min_y, p.y_m);
      max_y = i == 0 ? p.y_m : std::max(max_y, p.y_m);
    }
    const bool along_x = max_x - min_x >= max_y - min_y;
    std::stable_sort(order.begin(), order.end(), [along_x](const auto* a, const auto* b) {
      const double ka = along_x ? a->position.x_m : a->position.y_m;
      const double kb = along_x ? b->position.x_m : b->position.y_m;
      return std::tie(ka, a->id) < std::tie(kb, b->id);
    });
  } else {
    std::stable_sort(order.begin(), order.end(),
                     [](const auto* a, const auto* b) { return a->id < b->id; });
  }
  std::map<int, std::size_t> out;
  const std::size_t base = order.size() / workers;
  const std::size_t extra = order.size() % workers;
  std::size_t next = 0;
  for (std::size_t w = 0; w < workers; ++w) {
    const std::size_t count = base + (w < extra ? 1 : 0);
    for (std::size_t k = 0; k < count; ++k) out[order[next++]->id] = w;
  }
  return out;
}

std::vector<std::optional<std::size_t>> place_partitions(const config::scenario& scenario,
                                                         std::size_t workers) {
  const std::size_t count = std::max(1u, scenario.world.partitions);
  std::vector<std::optional<std::size_t>> out(count);
  if (workers == 0 || scenario.placement.crowd == config::crowd_placement::coordinator) return out;
  for (std::size_t i = 0; i < count; ++i) out[i] = i * workers / count;
  return out;
}

}  // namespace argus::actors
