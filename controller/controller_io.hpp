#pragma once

// What a camera node's controller takes in and gives out each frame. Everything here is the
// node's own knowledge: its pixels (boxes in its frame), its pan/tilt/zoom, and messages.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "opencv2/core/types.hpp"
#include "protocol/group_messages.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::controller {

using protocol::task_id;

/// What the controller asks its sensor to look for in the next frame: the target of `task`
/// by its signature. The sensor keeps what it needs to follow a target from frame to frame
/// (the tracker's last box) per task, and forgets a task no longer asked for.
struct look_request {
  task_id task = 0;
  protocol::signature target;
  friend bool operator==(const look_request&, const look_request&) = default;
};

/// What the sensor saw of one requested target in this frame.
struct look_result {
  task_id task = 0;
  bool found = false;
  /// The target's box in pixels (x, y the top-left corner).
  cv::Rect2d box;
  /// The acceptance score (histogram intersection, Fig. 9 step 5).
  double score = 0.0;
  /// Set in the frame the sensor re-took its model of her from this camera's pixels
  /// (sensing.signature_update): the signature it looks for from now on.
  std::optional<protocol::signature> model;
};

/// An operator's request (Section IV: "the operator selects a pedestrian to be observed in a
/// particular video feed"): the pedestrian's box in this camera's frame and its signature,
/// taken from the camera's own pixels.
struct operator_query {
  protocol::task_description task;
  cv::Rect2d box;
};

/// A delivered protocol message and the node it came from (its origin, not the last hop).
struct received_message {
  int origin = 0;
  protocol::group_message message;
};

/// One frame's inputs.
struct controller_input {
  std::int64_t tick = 0;
  /// The camera's pose in this frame.
  vision::ptz_state pose;
  /// Results for the looks requested in the previous step, in this frame.
  std::vector<look_result> looks;
  /// Operator requests addressed to this camera.
  std::vector<operator_query> queries;
  /// Messages delivered to this node, in canonical order.
  std::vector<received_message> messages;
  /// Tasks the operator ended through this camera.
  std::vector<task_id> cancels;
};

/// A message to send: to one node, or to every node within the hop limit (protocol::broadcast).
struct outgoing_message {
  int destination = 0;
  protocol::group_message message;
};

/// An event for the run's log: its kind and its JSON members (without braces).
struct controller_event {
  std::string kind;
  std::string fields_json;
};

/// One frame's outputs.
struct controller_output {
  std::vector<outgoing_message> messages;
  /// The pose to slew towards (the head moves at its own rates within its limits).
  std::optional<vision::ptz_state> command;
  /// What to look for in the next frame; empty = the node needs no image.
  std::vector<look_request> looks;
  std::vector<controller_event> events;
};

}  // namespace argus::controller
