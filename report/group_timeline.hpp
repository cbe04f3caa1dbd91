#pragma once

#include <string>
#include <vector>

#include "report/event_log.hpp"

namespace argus::report {

/// A camera's stay in a task's group, or its time as the group's leader: [from_s, to_s).
struct camera_span {
  int camera = 0;
  double from_s = 0.0;
  double to_s = 0.0;
};

/// A moment the network lost or regained a camera or a link (the fault injector's events).
struct failure_mark {
  double t_s = 0.0;
  int camera = 0;
  /// crash, crash_and_recover, link_cut, link_heal, loss_burst, or recovered.
  std::string kind;
};

/// One task's group over time, as the event log tells it.
struct task_timeline {
  int task = 0;
  /// The pedestrian the operator picked; -1 when no task_issued event names her.
  int pedestrian = -1;
  double start_s = 0.0;
  double end_s = 0.0;
  std::vector<camera_span> members;
  std::vector<camera_span> leaders;
  /// Times of hand-overs of the lead from one camera to another.
  std::vector<double> handoffs_s;
};

/// Who was in each task's group and who led, and the failures, over a whole run.
struct group_timeline {
  std::vector<task_timeline> tasks;
  std::vector<failure_mark> failures;
  double end_s = 0.0;

  /// Follows task_issued, task_created, joined, left_task, leader_changed, handoff,
  /// task_cancelled, fault and node_recovered events. A crashed camera leaves every group at
  /// once (it stops logging, so no left_task tells it); spans still open at the end of the
  /// log close at `end_s` (the run's duration when known, else the last event's time).
  static group_timeline from(const event_log& log, double end_s);
};

}  // namespace argus::report
