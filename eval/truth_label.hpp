#pragma once

#include <span>

#include "opencv2/core/types.hpp"
#include "vision/emulated_sensor.hpp"

namespace argus::eval {

/// What a track box really shows (docs/metrics.md).
struct truth_label {
  /// The visible pedestrian the box overlaps most (by area), or -1.
  int truth = -1;
  /// Intersection over union with the target's visible box; 0 when she is not visible.
  double iou = 0.0;
  /// The box shows the target (truth == target) and holds the centre of her visible box.
  bool observed = false;
};

/// Pedestrians hidden beyond this fraction do not count as visible: nobody could tell them.
inline constexpr double max_visible_occlusion = 0.9;

/// Labels `box` (pixels) against `visible` (vision::visible_pedestrians of the same frame and
/// view, boxes not yet clipped) in a `width` x `height` frame, for target `target`.
truth_label label_box(const cv::Rect2d& box, int target,
                      std::span<const vision::pedestrian_view> visible, int width, int height);

}  // namespace argus::eval
