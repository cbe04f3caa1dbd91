#pragma once

#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "controller/controller_io.hpp"
#include "opencv2/core.hpp"
#include "vision/tracker.hpp"

namespace argus::sensing {

/// A camera node's sensing on its own pixels (Section III-B): one colour-indexing tracker
/// (vision::tracker: ratio-histogram backprojection, Fig. 9 localisation, acceptance by
/// histogram intersection) per target the controller asks for. Node-side: it sees only the
/// frames it is given.
class pixel_sensor {
 public:
  /// A sensor whose trackers use `settings`.
  explicit pixel_sensor(vision::tracker_settings settings = {});

  /// The trackers' settings for a scenario's `sensing` block (tracker_scales, ego_motion).
  static vision::tracker_settings settings_for(const config::sensing_settings& sensing);

  /// Whether a box found for a task is on that task's pedestrian (sensing.identity:
  /// ground_truth; simulator knowledge, given by the node's host, never to the controller).
  using truth_check = std::function<bool(controller::task_id, const cv::Rect&)>;

  /// Looks for every requested target in `bgr`, taken at `pose`; trackers of targets no longer
  /// asked for are dropped, new ones search the whole frame. With ego-motion compensation on,
  /// each track's last box first follows the camera's move since the last frame. With
  /// `is_target`, each tracker takes the first of its candidate regions that is the task's
  /// pedestrian (vision::tracker::update with a check), or none.
  std::vector<controller::look_result> look(const cv::Mat& bgr, const vision::ptz_state& pose,
                                            const std::vector<controller::look_request>& looks,
                                            const truth_check& is_target = {});

  /// The operator picked the pedestrian in `box` for `task` in `bgr`, taken at `pose`: its
  /// signature from the pixels in the box, and a tracker started there.
  protocol::signature acquire(controller::task_id task, const cv::Mat& bgr,
                              const vision::ptz_state& pose, const cv::Rect& box);

 private:
  vision::tracker_settings settings_;
  std::map<controller::task_id, vision::tracker> trackers_;
  // The pose of the last frame looked at, for ego-motion compensation.
  std::optional<vision::ptz_state> last_pose_;
};

}  // namespace argus::sensing
