#include "actors/partition_shadow.hpp"

#include <iterator>

namespace argus::actors {

void partition_shadow::stepped(std::shared_ptr<const world::snapshot> previous,
                               std::vector<world::pedestrian>* whole,
                               std::vector<world::pedestrian> arrivals) {
  if (!whole) {
    since_.push_back({std::move(previous), std::move(arrivals)});
    return;
  }
  since_.clear();
  start_ = std::move(*whole);
  start_.insert(start_.end(), std::make_move_iterator(arrivals.begin()),
                std::make_move_iterator(arrivals.end()));
}

std::vector<world::pedestrian> partition_shadow::replay(
    const world::station& where, const world::partition_bounds& bounds,
    const world::behaviour_settings& behaviour) const {
  auto pedestrians = start_;
  for (const auto& input : since_) {
    auto result = world::partition_step(where, *input.previous, pedestrians, bounds, behaviour);
    pedestrians = std::move(result.pedestrians);
    pedestrians.insert(pedestrians.end(), input.arrivals.begin(), input.arrivals.end());
  }
  return pedestrians;
}

}  // namespace argus::actors
