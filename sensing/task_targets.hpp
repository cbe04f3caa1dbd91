#pragma once

// How an operator's task finds its pedestrian in a camera's frame (simulator knowledge that
// stands for the operator's eyes; it reaches the node only as a box).

#include <set>

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

/// Who is in view (as operator_box sees them).
std::set<int> in_view(const world::snapshot& frame, const world::station& where,
                      const vision::camera_view& view);

/// Watches a camera's view for the first pedestrian to enter it (Fig. 19): whoever is in view
/// when the watch starts does not count.
class entry_watch {
 public:
  /// The view when the watch starts.
  void prime(std::set<int> in_view_now) {
    before_ = std::move(in_view_now);
    primed_ = true;
  }
  /// The next frame's view: the lowest id that entered since the last frame, or 0.
  int step(const std::set<int>& in_view_now);

 private:
  std::set<int> before_;
  bool primed_ = false;
};

}  // namespace argus::sensing
