#pragma once

#include <filesystem>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "config/scenario.hpp"
#include "live/command.hpp"

namespace argus::live {

/// The commands a live run carried out, each at the tick it took effect; what
/// `DIR/commands.yaml` holds. The scenario script and the fault injector add to it from their
/// turns (any thread).
class command_log {
 public:
  /// Records that `c` took effect.
  void add(timed_command c) {
    std::lock_guard<std::mutex> guard(mutex_);
    entries_.push_back(std::move(c));
  }

  /// Every command so far, by tick (tasks before faults within a tick, each in its order).
  std::vector<timed_command> commands() const;

 private:
  mutable std::mutex mutex_;
  std::vector<timed_command> entries_;
};

/// `commands` as the YAML of `commands.yaml`:
///   scenario: station
///   seed: 1
///   commands:
///     - {tick: 150, command: task, task: 2, camera: 7, pixel: [160, 120], cameras_wanted: 1}
///     - {tick: 300, command: cut, camera: 1, peer: 2}
std::string commands_yaml(std::span<const timed_command> commands, const config::scenario& run);

/// Reads a `commands.yaml`. Throws std::runtime_error naming the file and the entry when it
/// cannot be read or an entry is malformed.
std::vector<timed_command> read_commands(const std::filesystem::path& file);

/// Adds `commands` to `scenario` the way `argus run` replays them: a task as a task (by pixel)
/// at its tick, a cancellation as its task's `cancel_at`, the others as faults (`crash`,
/// `recover`, `link_cut`, `link_heal`) at their tick. The scenario script and the fault
/// injector then do at those ticks what they did live, so the event log comes out the same.
/// Throws std::invalid_argument when a command does not fit the scenario (unknown camera, a
/// task index out of turn, a cancellation of a task that does not exist or already has one).
void apply_commands(config::scenario& scenario, std::span<const timed_command> commands);

}  // namespace argus::live
