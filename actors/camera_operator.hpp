#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "actors/operator_board.hpp"
#include "config/scenario.hpp"
#include "controller/controller_io.hpp"
#include "events/event.hpp"
#include "sensing/sensor.hpp"
#include "sensing/task_targets.hpp"

namespace argus::actors {

/// Where an operator's pick for a camera went: the pedestrian it named, the camera, the tick.
struct task_pick {
  protocol::task_id task = 0;
  int pedestrian = 0;
  int camera = 0;
  std::int64_t tick = 0;
  config::task_target by = config::task_target::pedestrian;
};

/// The simulated operator at one camera's monitor (Section IV: "the operator selects a
/// pedestrian to be observed in a particular video feed"): the scenario's tasks and
/// cancellations for this camera, the live operator's orders (argus serve), and the watches for
/// the first to enter the view. A due pick is resolved against the frame into the pedestrian's
/// box, and the node's own sensor takes her signature from it; or it is refused (logged
/// `task_refused`) when she is not in view.
class camera_operator {
 public:
  camera_operator(const config::scenario& scenario, int camera_id);

  /// Merges the live orders for this camera published since the last call.
  void take_orders(const operator_board& board);

  /// The picks due at `tick` (those given before `first_turn`, while the camera was down, are
  /// lost with it); returns the tasks cancelled now.
  std::vector<protocol::task_id> take_due(std::int64_t tick, std::int64_t first_turn);

  /// Whether a pick or a watch needs this tick's frame.
  bool wants_frame() const { return !due_.empty() || !watches_.empty(); }

  /// What resolving a pick reports: its event (kind, JSON members) and, once resolved, where it
  /// went.
  using event_sink = std::function<void(const events::event&)>;
  using pick_sink = std::function<void(const task_pick&)>;

  /// Resolves the due picks and the watches against `frame` (null: no frame this tick) into
  /// queries for the strategy, taking each signature with the node's sensor `eye` (set whenever
  /// `frame` is) when `with_signature`.
  std::vector<controller::operator_query> resolve(const sensing::sensed_frame* frame,
                                                  sensing::sensor* eye, bool with_signature,
                                                  const event_sink& emit, const pick_sink& picked);

 private:
  struct due_task {
    std::int64_t tick = 0;
    protocol::task_id task = 0;
    config::operator_task request;
  };
  struct watch {
    due_task task;
    sensing::entry_watch entries;
  };

  void resolve_one(const due_task& q, const sensing::sensed_frame* frame, sensing::sensor* eye,
                   bool with_signature, int entered, const event_sink& emit,
                   const pick_sink& picked, std::vector<controller::operator_query>& out) const;

  int camera_id_;
  std::vector<due_task> tasks_;
  std::size_t next_task_ = 0;
  // Cancellations of tasks issued through this camera: (tick, task), by tick.
  std::vector<std::pair<std::int64_t, protocol::task_id>> cancels_;
  std::size_t next_cancel_ = 0;
  std::size_t board_cursor_ = 0;
  std::vector<due_task> due_;
  std::vector<watch> watches_;
};

}  // namespace argus::actors
