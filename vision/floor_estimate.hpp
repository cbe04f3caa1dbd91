#pragma once

// Where a calibrated camera puts a tracked box on the floor (sensing.group_geometry:
// calibrated), the 3-D location the paper names (Section V) as the way to detect pedestrian
// identification errors, and the test of whether a find can be the pedestrian the group saw.

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/types.hpp>
#include <optional>

#include "vision/ptz_camera.hpp"

namespace argus::vision {

/// A point on the floor where a camera saw her, how far off it may be, and when.
struct floor_estimate {
  Eigen::Vector2d where{0.0, 0.0};
  double radius_m = 0.0;
  std::int64_t tick = 0;
  /// Whether the find it came from was tested against a confirmed estimate (or was the
  /// operator's pick): only a confirmed estimate refuses finds, so that a group that has lost
  /// her and taken a stranger does not also refuse her where she is found again.
  bool confirmed = true;
};

/// The rules of the estimate: the height assumed for a body whose feet are cut off, how fast
/// she may have walked since the group's estimate, and the slack on every comparison (a colour
/// tracker's box is not her silhouette: in a Penn Station run her boxes' floor points were a
/// metre off at the median, 2.3 m at the 90th percentile; bench/RESULTS.md).
struct floor_rules {
  double assumed_height_m = 1.7;
  double walking_speed_mps = 2.0;
  double slack_m = 3.0;
  /// How long the group's last estimate is trusted.
  double trusted_s = 10.0;
};

/// Where `view` puts `box` on the floor: under the centre of its bottom edge, or, when that
/// edge is the frame's own (her feet cut off), over the centre of its top edge at
/// `rules.assumed_height_m`. The radius is how far four pixels up or down would move the point
/// (and 0.3 m more for the assumed height). None when the ray never meets that plane.
std::optional<floor_estimate> floor_estimate_of(const camera_view& view, const cv::Rect2d& box,
                                                std::int64_t tick, const floor_rules& rules = {});

/// Whether a find is confirmed: when it was tested against `expected`, the group's trusted
/// estimate, as that estimate was; with none, only the task's first (the operator's pick).
bool confirmed_by(const std::optional<floor_estimate>& expected, bool first_of_task);

/// Whether a find at `found` can be the pedestrian estimated at `expected`, `age_s` earlier:
/// within both radii, the slack and the walk she could have made since.
bool could_be(const floor_estimate& found, const floor_estimate& expected, double age_s,
              const floor_rules& rules = {});

}  // namespace argus::vision
