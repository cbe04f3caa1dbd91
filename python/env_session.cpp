#include "python/env_session.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include "actors/run_scenario.hpp"
#include "config/field_override.hpp"
#include "config/scenario_loader.hpp"
#include "config/ticks.hpp"
#include "controller/strategy_registry.hpp"
#include "fmt/format.h"
#include "python/env_agent.hpp"
#include "python/set_texts.hpp"

namespace argus::pybridge {

env_session::env_session(const std::string& scenario_file, const std::vector<std::string>& set)
    : scenario_(config::load_scenario(scenario_file, overrides_from(set))) {
  static std::atomic<int> sessions{0};
  strategy_name_ = fmt::format("env:{}", ++sessions);
}

env_session::~env_session() {
  close();
}

std::vector<controller::node_identity> env_session::cameras() const {
  std::vector<controller::node_identity> out;
  for (const auto& c : scenario_.cameras) out.push_back(controller::node_identity::from(c));
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return out;
}

bool env_session::pixels() const {
  return scenario_.sensing.mode == config::sensing_mode::pixels;
}

env_exchange::collected env_session::reset(std::optional<std::uint64_t> seed,
                                           const std::filesystem::path& output_dir) {
  close();
  auto exchange = std::make_shared<env_exchange>();
  exchange_ = exchange;
  auto scenario = scenario_;
  // The session's one name, now standing for this run's agents (the last run's are gone).
  scenario.controller.strategy = strategy_name_;
  controller::register_strategy(
      {scenario.controller.strategy,
       [exchange](const controller::strategy_context& c) -> std::unique_ptr<controller::strategy> {
         return std::make_unique<env_agent>(c.me, exchange);
       },
       false, "a camera stepped by argus.parallel_env"});
  if (seed) scenario.run.seed = *seed;
  scenario.run.output_dir = output_dir.string();
  // Every camera's agent waits for Python inside its turn, on a scheduler thread of its own;
  // the spare threads run the world, the links and the clock. The lockstep makes the run the
  // same whatever the thread count.
  scenario.run.threads = static_cast<unsigned>(scenario.cameras.size() + 3);
  scenario.run.speed = 0.0;
  run_ = std::thread([scenario, exchange] {
    try {
      actors::run_options options;
      options.render_threads = 2;
      auto outcome = actors::run_scenario(scenario, options);
      exchange->finish(outcome.result.failure);
    } catch (const std::exception& e) {
      exchange->finish(e.what());
    }
  });
  end_tick_ = config::to_ticks(scenario.run.duration, scenario.run.tick);
  auto c = exchange->wait(end_tick_ <= 0);
  tick_ = c.tick;
  return c;
}

env_exchange::collected env_session::step(std::map<int, env_action> actions) {
  if (!exchange_) throw std::logic_error("step() before reset()");
  exchange_->answer(std::move(actions));
  auto c = exchange_->wait(tick_ + 1 >= end_tick_);
  if (c.tick >= 0) tick_ = c.tick;
  return c;
}

void env_session::close() {
  if (exchange_) exchange_->abandon();
  if (run_.joinable()) run_.join();
  exchange_.reset();
}

}  // namespace argus::pybridge
