#pragma once

// What a camera node's controller takes in and gives out each frame. Everything here is the
// node's own knowledge: its pixels (boxes in its frame), its pan/tilt/zoom, and messages.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "events/event.hpp"
#include "opencv2/core/mat.hpp"
#include "opencv2/core/types.hpp"
#include "protocol/group_messages.hpp"
#include "protocol/net_message.hpp"
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

/// A signature the sensor took at the strategy's request (controller_output::acquire).
struct acquired_signature {
  task_id task = 0;
  protocol::signature signature;
};

/// One frame's inputs.
struct controller_input {
  std::int64_t tick = 0;
  /// The camera's pose in this frame.
  vision::ptz_state pose;
  /// The frame the node sensed, as its sensor saw it (degraded): empty when it took none or
  /// senses without pixels (emulated). For strategies that do their own vision.
  cv::Mat image;
  /// Whether the node took a frame this tick (it does when the strategy asked to look for
  /// someone or wanted a frame; an idle node takes none). A frame whose rendering failed counts:
  /// its looks then find nothing.
  bool sensed = false;
  /// Results for the looks requested in the previous step, in this frame.
  std::vector<look_result> looks;
  /// The signatures taken in the last frame at this strategy's request (its `acquire`).
  std::vector<acquired_signature> acquired;
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

/// An event for the run's log: its kind and its JSON members (without braces). The log's own
/// kinds are made from their structs (events/event.hpp) with `logged`; a strategy may log kinds
/// of its own.
struct controller_event {
  std::string kind;
  std::string fields_json;
};

/// The log line of `e`, one of the vocabulary's events.
inline controller_event logged(const events::event& e) {
  return {std::string(events::kind_of(e)), events::fields_json(e)};
}

/// Take the model of whoever is in `box` of the frame just sensed as task `task`'s target: the
/// sensor takes her signature there and starts following her, the node looks for her in the
/// next frame (as if asked to), and the signature comes back in the next input's `acquired`.
/// Ignored when the frame has nothing to take it from (a failed rendering).
struct acquire_request {
  task_id task = 0;
  cv::Rect2d box;
};

/// One frame's outputs.
struct controller_output {
  std::vector<outgoing_message> messages;
  /// The pose to slew towards (the head moves at its own rates within its limits).
  std::optional<vision::ptz_state> command;
  /// What to look for in the next frame; empty = the node needs no image.
  std::vector<look_request> looks;
  std::vector<controller_event> events;
  /// Signatures to take from this frame (see acquire_request).
  std::vector<acquire_request> acquire;
};

}  // namespace argus::controller
