#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "config/scenario.hpp"
#include "controller/strategy.hpp"
#include "python/env_exchange.hpp"

namespace argus::pybridge {

/// The C++ half of argus.parallel_env: a scenario run in a thread of its own, each camera's
/// strategy an env_agent, stepped tick by tick from Python. Not thread-safe: one Python
/// environment drives it.
class env_session {
 public:
  /// Loads `scenario_file` with the `KEY=VALUE` overrides `set` (config::scenario_error names
  /// a bad field).
  env_session(const std::string& scenario_file, const std::vector<std::string>& set);
  ~env_session();
  env_session(const env_session&) = delete;
  env_session& operator=(const env_session&) = delete;

  const config::scenario& scenario() const { return scenario_; }
  std::vector<controller::node_identity> cameras() const;
  bool pixels() const;

  /// Abandons the run in progress, if any, and starts one with `seed` (none: the scenario's),
  /// writing to `output_dir`; returns the first tick's inputs.
  env_exchange::collected reset(std::optional<std::uint64_t> seed,
                                const std::filesystem::path& output_dir);
  /// Answers the tick collected last; returns the next one's inputs.
  env_exchange::collected step(std::map<int, env_action> actions);
  /// Abandons the run in progress and waits for its thread.
  void close();

 private:
  config::scenario scenario_;
  // The registry's name for this session's agents.
  std::string strategy_name_;
  std::shared_ptr<env_exchange> exchange_;
  std::thread run_;
  // The run's end tick, and the tick collected last.
  std::int64_t end_tick_ = 0;
  std::int64_t tick_ = -1;
};

}  // namespace argus::pybridge
