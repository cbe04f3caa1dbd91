#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "config/scenario.hpp"
#include "controller/strategy.hpp"
#include "eval/observation_log.hpp"
#include "vision/ptz_camera.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::eval {

/// What the evaluation's instruments know of one camera and the world it watches: simulator
/// knowledge, kept out of the camera node and out of its strategy.
struct camera_truth {
  config::camera_settings camera;
  config::seconds tick_length{1.0 / 15.0};
  std::shared_ptr<const world::station> station;
  /// The world in the current tick (null before the first).
  std::function<std::shared_ptr<const world::snapshot>()> now;
  std::shared_ptr<observation_log> log;

  /// The camera's view at `pose`.
  vision::camera_view view(const vision::ptz_state& pose) const;
  /// Task `task`'s target, once known.
  std::optional<int> target_of(controller::task_id task) const;
};

/// The task whose target a node looks for without holding her, after a step that returned
/// `out` with status `s`: bidding with nothing found in this frame (`found_now` false), or
/// performing the task with its tracker in Wait or Search; none otherwise.
std::optional<controller::task_id> looked_for_unheld(const controller::strategy_status& s,
                                                     const controller::controller_output& out,
                                                     bool found_now);

/// Whether any look of `in` found its target.
bool found_any(const controller::controller_input& in);

}  // namespace argus::eval
