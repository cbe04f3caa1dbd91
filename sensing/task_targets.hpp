#pragma once

// How an operator's task finds its pedestrian in a camera's frame (simulator knowledge that
// stands for the operator's eyes; it reaches the node only as a box).

#include <set>
#include <vector>

#include "opencv2/core/types.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::world {
class snapshot;
class station;
}  // namespace argus::world

namespace argus::sensing {

/// The pedestrian the operator clicks on at `pixel`: the nearest one whose visible box holds
/// it (hidden no more than operator_box allows), or 0 when the click hits nobody.
int pedestrian_at(const world::snapshot& frame, const world::station& where,
                  const vision::camera_view& view, const cv::Point2d& pixel);

/// Who is in a camera's view: at all (as operator_box sees them), and wholly (inside the frame,
/// hardly hidden and a fourteenth of the frame tall, so that a signature taken from her box is
/// hers and a tracker can follow her).
struct view_census {
  std::set<int> seen;
  std::set<int> whole;
};
view_census in_view(const world::snapshot& frame, const world::station& where,
                    const vision::camera_view& view);

/// Watches a camera's view for the first pedestrian to enter it (Fig. 19): whoever is in view
/// when the watch starts does not count. The first to enter is taken once she is wholly in
/// view: a body half across the frame's edge, or a figure far away, would give the task a
/// signature of a few pixels. Of those who entered and are still in view, the earliest to enter
/// that is wholly in view is taken.
class entry_watch {
 public:
  /// The view when the watch starts.
  void prime(const view_census& now) {
    before_ = now.seen;
    primed_ = true;
  }
  /// The next frame's view: the first to enter, once wholly in view; 0 until then.
  int step(const view_census& now);

 private:
  std::set<int> before_;
  std::vector<int> entrants_;  // in order of entry
  bool primed_ = false;
};

}  // namespace argus::sensing
