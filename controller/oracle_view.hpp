#pragma once

#include <cstdint>
#include <optional>

#include "controller/controller_io.hpp"
#include "opencv2/core/types.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::controller {

/// Ground truth, as one camera's oracle strategy may see it: the central assignment of cameras
/// to tasks and where each task's target is. The simulator gives it only to a strategy
/// registered as an oracle (controller/strategy_registry.hpp); an upper bound to compare
/// strategies against, not something a camera could know.
class oracle_view {
 public:
  virtual ~oracle_view() = default;

  /// The task the central oracle gives this camera in the frame of `tick`, if any.
  virtual std::optional<task_id> task_of(std::int64_t tick) = 0;

  /// The pose that centres task `task`'s target in this camera's view in the current frame: a
  /// third of the frame's height with `zoom`, else at the default field of view.
  virtual vision::ptz_state pose_on(task_id task, bool zoom) = 0;

  /// Where task `task`'s target shows in this camera's frame taken at `pose`, if she is in view.
  virtual std::optional<cv::Rect2d> target_box(task_id task, const vision::ptz_state& pose) = 0;

  /// The signature the operator's pick gave task `task`, once the tasked camera left it here.
  virtual std::optional<protocol::signature> picked_signature(task_id task) = 0;
  virtual void put_picked_signature(task_id task, protocol::signature signature) = 0;
};

}  // namespace argus::controller
