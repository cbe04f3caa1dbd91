#pragma once

#include <cstdint>
#include <vector>

#include "actors/camera_operator.hpp"
#include "controller/controller_io.hpp"
#include "opencv2/core/mat.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::actors {

/// What the host of a run watches camera nodes through: the live console's display and the
/// evaluation's record of the operator's picks. Nothing comes back to the node. Called from
/// the node's turn (phase cameras), on any thread.
class node_observer {
 public:
  virtual ~node_observer() = default;
  /// Network messages camera `camera` handed to its links / took from them in its turn.
  virtual void traffic(int camera, std::uint64_t sent, std::uint64_t received) = 0;
  /// The operator's pick at camera `pick.camera` went to pedestrian `pick.pedestrian`.
  virtual void picked(const task_pick& pick) = 0;
  /// Camera `camera`'s turn of `tick` is over: its pose after moving, its frame (empty when it
  /// rendered none) and what its sensor found in it.
  virtual void turn_done(int camera, std::int64_t tick, const vision::ptz_state& pose,
                         const cv::Mat& image,
                         const std::vector<controller::look_result>& looks) = 0;
};

}  // namespace argus::actors
