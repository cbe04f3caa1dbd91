#include "world/crowd.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

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
  const auto& speed = scenario.world.speed;
  out.speeds = {speed.mean_mps, speed.sd_mps, speed.min_mps, speed.max_mps};
  out.clothes = scenario.world.clothes;
  for (const auto& f : scenario.world.flows) {
    flow each;
    each.name = f.name;
    each.spawn_area = {{f.spawn.min_x_m, f.spawn.min_y_m}, {f.spawn.max_x_m, f.spawn.max_y_m}};
    each.count = f.count;
    each.rate_per_s = f.rate_per_s;
    each.start_s = f.start.count();
    each.exit_name = f.exit;
    out.flows.push_back(std::move(each));
  }
  out.source_path = scenario.source_path;
  return out;
}

spawner_settings crowd_settings::spawning(const station& where) const {
  spawner_settings out{run_seed, population, spawn_rate_per_min, behaviour.tick_s, speeds,
                       clothes,  flows};
  std::vector<config::problem> problems;
  const auto& portals = where.plan().portals;
  for (std::size_t i = 0; i < out.flows.size(); ++i) {
    auto& f = out.flows[i];
    if (f.exit_portal >= 0 && static_cast<std::size_t>(f.exit_portal) < portals.size()) continue;
    const auto named = std::find_if(portals.begin(), portals.end(),
                                    [&](const portal& p) { return p.name == f.exit_name; });
    if (named == portals.end()) {
      std::vector<std::string> names;
      for (const auto& p : portals) names.push_back("'" + p.name + "'");
      problems.push_back(
          {source_path, 0, 0, fmt::format("world.flows[{}].exit", i),
           fmt::format("expected the name of a portal of layout {} ({}), got '{}'",
                       where.plan().source_path, fmt::join(names, ", "), f.exit_name)});
      continue;
    }
    f.exit_portal = static_cast<int>(named - portals.begin());
  }
  if (!problems.empty()) throw config::scenario_error(std::move(problems));
  return out;
}

crowd::crowd(std::shared_ptr<const station> where, crowd_settings settings)
    : station_(std::move(where)),
      settings_(settings),
      spawner_(settings.spawning(*station_)),
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
  auto states = gather_states(results);
  auto spawned = spawner_.spawn(*station_, states, tick, spawn_events);
  current_ =
      merge(*station_, tick,
            std::chrono::duration<double>{static_cast<double>(tick) * settings_.behaviour.tick_s},
            std::move(states), results, spawned, std::move(spawn_events));
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
