#pragma once

// What a run records for its evaluation against ground truth: each camera's frames (pose,
// state, what it tracked and whom that really was), the targets' true paths, and where each
// task came from. The camera node never reads any of it back.

#include <cstdint>
#include <string>
#include <vector>

#include "opencv2/core/types.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::eval {

/// One task's track box in one camera frame, labelled with the truth.
struct look_record {
  std::uint32_t task = 0;
  bool leader = false;
  bool found = false;
  /// The tracker's box in pixels (empty when not found).
  cv::Rect2d box;
  double score = 0.0;
  /// Whom the box shows: the visible pedestrian it overlaps most, or -1 (docs/metrics.md).
  int truth = -1;
  /// Intersection over union with the target's visible box (0 when she is not visible).
  double iou = 0.0;
  /// Whether the box counts as observing the target: it shows her and holds her centre.
  bool observed = false;
};

/// A pedestrian's visible box in a camera frame (MOTChallenge ground truth).
struct visible_box {
  int pedestrian = 0;
  cv::Rect2d box;  // clipped to the frame
  /// Fraction of the body box that is visible, in [0, 1].
  double visibility = 0.0;
};

/// Fig. 10's top-level state of a node in a frame, as the log names it.
enum class frame_state : std::uint8_t { idle, computing_relevance, performing_task };

/// One camera's frame: its pose and state, its tasks' looks, and (for MOT export) everyone
/// visible in it.
struct camera_frame {
  std::int64_t tick = 0;
  int camera = 0;
  vision::ptz_state pose;
  frame_state state = frame_state::idle;
  std::vector<look_record> looks;
  std::vector<visible_box> visible;
};

/// How a task's target was chosen.
enum class target_choice : std::uint8_t { pedestrian, pixel, first_to_enter };

/// Where a task started: the operator's camera, the pedestrian it settled on and when.
struct task_origin {
  std::uint32_t task = 0;
  int pedestrian = 0;
  int camera = 0;
  std::int64_t tick = 0;
  target_choice by = target_choice::pedestrian;
};

/// A target's true state in one tick (from the world's snapshot).
struct target_sample {
  std::int64_t tick = 0;
  std::uint32_t task = 0;
  int pedestrian = 0;
  double x_m = 0.0;
  double y_m = 0.0;
  double height_m = 1.7;
  /// Whether she is in the station in this tick.
  bool present = false;
};

/// Messages a node sent for a task, by kind.
struct sent_count {
  std::uint32_t task = 0;
  std::string kind;
  std::uint64_t count = 0;
};

}  // namespace argus::eval
