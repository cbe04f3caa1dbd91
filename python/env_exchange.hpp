#pragma once

// The meeting point of argus.parallel_env and a running simulation: each tick, every camera's
// agent (env_agent) hands over what its node sensed and waits for the Python side's action; the
// environment waits until every live camera has done so. The run stays in lockstep, so the
// same seed and the same actions give the same trajectory, whatever the thread count.

#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "controller/controller_io.hpp"

namespace argus::pybridge {

/// One camera's action for one tick (argus.parallel_env's step).
struct env_action {
  /// The pose to slew towards; none: hold the current command.
  std::optional<vision::ptz_state> command;
  /// The tasks to look for in the next frame; none: every task the camera knows.
  std::optional<std::vector<controller::task_id>> looks;
  std::vector<controller::outgoing_message> messages;
};

/// Thrown into an agent when its environment abandons the run (a new reset, close): the node
/// ends the run after this tick.
struct env_abandoned : std::runtime_error {
  env_abandoned() : std::runtime_error("the environment abandoned this run (reset or close)") {}
};

class env_exchange {
 public:
  /// What the environment collects for one tick.
  struct collected {
    std::int64_t tick = -1;
    /// The input of each camera that stepped, by camera id.
    std::map<int, controller::controller_input> inputs;
    /// Cameras gone since the last collection (crashed).
    std::vector<int> gone;
    /// The run is over (its end, or a failure in `error`).
    bool finished = false;
    std::string error;
  };

  // The agents' side (CAF threads).
  void joined(int camera);
  void left(int camera);
  /// Posts this tick's input and waits for the action; throws env_abandoned.
  env_action exchange(int camera, controller::controller_input in);

  // The environment's side (the Python thread, without the GIL).
  /// Waits until every live camera has posted this tick's input, or the run is over
  /// (`until_finished`: only that, after the last tick).
  collected wait(bool until_finished = false);
  /// Answers every posted camera (none named: an empty action).
  void answer(std::map<int, env_action> actions);
  /// The run ended (error empty) or failed.
  void finish(std::string error);
  /// Abandons the run: agents waiting now and later are released with env_abandoned.
  void abandon();

 private:
  struct slot {
    bool live = false;
    bool posted = false;
    std::optional<controller::controller_input> input;
    std::optional<env_action> action;
  };

  std::mutex mutex_;
  std::condition_variable agents_;
  std::condition_variable environment_;
  std::map<int, slot> slots_;
  std::vector<int> gone_;
  bool finished_ = false;
  bool abandoned_ = false;
  std::string error_;
};

}  // namespace argus::pybridge
