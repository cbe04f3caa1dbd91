#include "world/crowd.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace argus::world {

crowd_settings crowd_settings::from(const config::scenario& scenario) {
  crowd_settings out;
  out.run_seed = scenario.run.seed;
  out.population = scenario.world.population;
  out.spawn_rate_per_min = scenario.world.spawn_rate_per_min;
  out.partitions = scenario.world.partitions;
  out.behaviour.tick_s = scenario.run.tick.count();
  return out;
}

crowd::crowd(std::shared_ptr<const station> where, crowd_settings settings)
    : station_(std::move(where)),
      settings_(settings),
      spawner_({settings.run_seed, settings.population, settings.spawn_rate_per_min,
                settings.behaviour.tick_s}),
      bounds_(vertical_strips(*station_, settings.partitions)),
      owned_(bounds_.size()) {
  // The neighbour index reaches 2 m; at up to 2.1 m/s two pedestrians close at most
  // 4.2 m/s, so a tick must stay short enough that no one can skip past a constraint.
  if (settings.behaviour.tick_s <= 0.0 || settings.behaviour.tick_s > 0.25) {
    throw std::invalid_argument("crowd: tick must be in (0, 0.25] s");
  }
  std::vector<event> events;
  std::vector<pedestrian> initial;
  if (settings_.prefill) initial = spawner_.populate(*station_, 0, events);
  std::vector<pedestrian_state> states;
  for (auto& p : initial) {
    states.push_back(p.state);
    owned_[owner_of(bounds_, p.state.position)].push_back(std::move(p));
  }
  current_ = std::make_shared<const snapshot>(*station_, 0, std::chrono::duration<double>{0.0},
                                              std::move(states), std::move(events));
}

void crowd::step() {
  const auto tick = current_->tick() + 1;
  std::vector<partition_result> results(bounds_.size());
  for (std::size_t i = 0; i < bounds_.size(); ++i) {
    results[i] = partition_step(*station_, *current_, owned_[i], bounds_[i], settings_.behaviour);
  }
  std::vector<event> spawn_events;
  const auto states = gather_states(results);
  auto spawned = spawner_.spawn(*station_, states, tick, spawn_events);
  current_ =
      merge(*station_, tick,
            std::chrono::duration<double>{static_cast<double>(tick) * settings_.behaviour.tick_s},
            results, spawned, std::move(spawn_events));
  last_hand_overs_ = 0;
  for (std::size_t i = 0; i < bounds_.size(); ++i) owned_[i] = std::move(results[i].pedestrians);
  for (auto& r : results) {
    for (auto& p : r.handed_over) {
      ++last_hand_overs_;
      owned_[owner_of(bounds_, p.state.position)].push_back(std::move(p));
    }
  }
  for (auto& p : spawned) owned_[owner_of(bounds_, p.state.position)].push_back(std::move(p));
}

}  // namespace argus::world
