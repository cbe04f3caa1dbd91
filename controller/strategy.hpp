#pragma once

// The public interface of a camera strategy: what a camera node's decision-making sees each
// frame and what it returns. Plain C++ (no CAF), so that a strategy can be written, tested and
// loaded without the runtime: the paper's controller (camera_controller), the no-collaboration
// baseline and the ground-truth oracle are implementations of it, as are plug-ins
// (docs/strategies.md).

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "config/scenario.hpp"
#include "controller/controller_io.hpp"
#include "vision/frame_size.hpp"
#include "vision/ptz_camera.hpp"
#include "vision/tracking_state.hpp"

namespace argus::controller {

/// What a camera node knows of itself: its id, its head's limits and rates, its default pose
/// and its frame size. No position, no calibration (Section I-B).
struct node_identity {
  int id = 0;
  vision::ptz_limits limits;
  vision::ptz_state home;
  vision::frame_size frame;
  /// The identity of a scenario camera.
  static node_identity from(const config::camera_settings& camera);
};

/// The top level of Fig. 10. A strategy that is no Fig. 10 controller reports `idle` while it
/// has no task and `performing_task` while it has one.
enum class node_state { idle, computing_relevance, performing_task };

/// A node's part in its group.
enum class group_role { member, leader };

/// Its name in the event log: "idle", "computing_relevance", "performing_task".
std::string_view name_of(node_state s);

/// What a strategy tells the node and the evaluation of itself: its top-level state (the node
/// actor's behaviour), the task it performs, its role in that task's group and, while it
/// performs one, its tracker's state (Fig. 10's inset).
struct strategy_status {
  node_state state = node_state::idle;
  std::optional<task_id> task;
  group_role role = group_role::member;
  vision::tracking_state tracking = vision::tracking_state::track;
};

/// What a strategy decides before its frame is sensed: whether it wants a frame this tick
/// even if it asked to look for nobody, and events to log first.
struct frame_plan {
  bool wants_frame = false;
  std::vector<controller_event> events;
};

/// A camera strategy: one per camera node, stepped once per frame, never from two threads at
/// once. It knows only what its node knows (its pixels' boxes, its pose, messages) unless it is
/// registered as an oracle (controller/oracle_view.hpp).
class strategy {
 public:
  virtual ~strategy() = default;

  /// The frame of `tick` is about to be sensed; `looking`: whether the node has looks to make
  /// in it (those the last step asked for). The default wants the frame when it is looking.
  virtual frame_plan plan(std::int64_t tick, bool looking) {
    (void)tick;
    frame_plan p;
    p.wants_frame = looking;
    return p;
  }

  /// One frame: what the node sensed, received and was asked; what it is to do.
  virtual controller_output step(const controller_input& in) = 0;

  /// Its state after the last step.
  virtual strategy_status status() const = 0;

  /// Whether the operator's picks reach it as queries carrying the pedestrian's signature,
  /// which the node takes from its own sensor (and which starts the sensor's tracking of her).
  /// A strategy that answers false still gets the queries, with an empty signature.
  virtual bool takes_operator_signatures() const { return true; }
};

/// A strategy that passes everything to another, for instruments that watch or adjust one
/// (eval/): override what it changes and call the inner one.
class strategy_wrapper : public strategy {
 public:
  explicit strategy_wrapper(std::unique_ptr<strategy> inner) : inner_(std::move(inner)) {}
  frame_plan plan(std::int64_t tick, bool looking) override { return inner_->plan(tick, looking); }
  controller_output step(const controller_input& in) override { return inner_->step(in); }
  strategy_status status() const override { return inner_->status(); }
  bool takes_operator_signatures() const override { return inner_->takes_operator_signatures(); }

 protected:
  strategy& inner() { return *inner_; }
  const strategy& inner() const { return *inner_; }

 private:
  std::unique_ptr<strategy> inner_;
};

}  // namespace argus::controller
