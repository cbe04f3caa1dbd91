#pragma once

// What a camera's strategy decides (docs/events.md, "Camera strategy"): the events of the
// paper's controller and of the oracle, source `camera/<id>`. Each starts with the emitting
// camera's id.

#include <cstdint>
#include <string>
#include <vector>

#include "events/members.hpp"

namespace argus::events {

using task_id = std::uint32_t;

struct node_state {
  static constexpr std::string_view name = "node_state";
  int camera = 0;
  std::string from, to;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("from", from), f("to", to);
  }
};

struct tracking {
  static constexpr std::string_view name = "tracking";
  int camera = 0;
  task_id task = 0;
  std::string state;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("state", state);
  }
};

struct signature_shared {
  static constexpr std::string_view name = "signature_shared";
  int camera = 0;
  task_id task = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task);
  }
};

struct task_created {
  static constexpr std::string_view name = "task_created";
  int camera = 0;
  task_id task = 0;
  unsigned min_cameras = 0, max_cameras = 0;
  fixed<4> relevance;
  std::uint64_t term = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("min_cameras", min_cameras),
        f("max_cameras", max_cameras), f("relevance", relevance), f("term", term);
  }
};

struct queried {
  static constexpr std::string_view name = "queried";
  int camera = 0;
  task_id task = 0;
  int leader = 0;
  std::uint32_t auction = 0;
  int from = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("leader", leader), f("auction", auction),
        f("from", from);
  }
};

struct bid {
  static constexpr std::string_view name = "bid";
  int camera = 0;
  task_id task = 0;
  int leader = 0;
  std::uint32_t auction = 0;
  fixed<4> relevance;
  bool busy = false;
  fixed<3> found_fraction;
  fixed<4> mean_score;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("leader", leader), f("auction", auction),
        f("relevance", relevance), f("busy", busy), f("found_fraction", found_fraction),
        f("mean_score", mean_score);
  }
};

struct query_dropped {
  static constexpr std::string_view name = "query_dropped";
  int camera = 0;
  task_id task = 0;
  int leader = 0;
  std::string reason;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("leader", leader), f("reason", reason);
  }
};

struct join_refused {
  static constexpr std::string_view name = "join_refused";
  int camera = 0;
  task_id task = 0;
  int leader = 0;
  task_id busy_with = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("leader", leader), f("busy_with", busy_with);
  }
};

struct joined {
  static constexpr std::string_view name = "joined";
  int camera = 0;
  task_id task = 0;
  int leader = 0;
  bool reassign = false;
  std::uint64_t term = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("leader", leader), f("reassign", reassign),
        f("term", term);
  }
};

struct left_task {
  static constexpr std::string_view name = "left_task";
  int camera = 0;
  task_id task = 0;
  std::string reason, role;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("reason", reason), f("role", role);
  }
};

struct group_vanished {
  static constexpr std::string_view name = "group_vanished";
  int camera = 0;
  task_id task = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task);
  }
};

/// member_added or member_dropped (`added`): its leader counts a member, or stops counting one.
struct member_change {
  static constexpr std::string_view name = "member_added";
  int camera = 0;
  task_id task = 0;
  int member = 0;
  std::string reason;
  bool added = true;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("member", member), f("reason", reason);
  }
};

struct cancel_heard {
  static constexpr std::string_view name = "cancel_heard";
  int camera = 0;
  task_id task = 0;
  int from = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("from", from);
  }
};

struct auction_started {
  static constexpr std::string_view name = "auction";
  int camera = 0;
  task_id task = 0;
  std::uint32_t auction = 0;
  std::uint64_t group_size = 0;
  fixed<4> relevance;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("auction", auction), f("group_size", group_size),
        f("relevance", relevance);
  }
};

struct auction_closed {
  static constexpr std::string_view name = "auction_closed";
  int camera = 0;
  task_id task = 0;
  std::uint32_t auction = 0;
  std::uint64_t bids = 0;
  std::vector<int> chosen;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("auction", auction), f("bids", bids),
        f("chosen", chosen);
  }
};

struct invited {
  static constexpr std::string_view name = "invited";
  int camera = 0;
  task_id task = 0;
  int member = 0;
  bool reassign = false;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("member", member), f("reassign", reassign);
  }
};

struct handoff {
  static constexpr std::string_view name = "handoff";
  int camera = 0;
  task_id task = 0;
  int from = 0, to = 0;
  fixed<4> relevance;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("from", from), f("to", to), f("relevance", relevance);
  }
};

struct leader_changed {
  static constexpr std::string_view name = "leader_changed";
  int camera = 0;
  task_id task = 0;
  int leader = 0, previous = 0;
  std::string reason;
  std::uint64_t term = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("leader", leader), f("previous", previous),
        f("reason", reason), f("term", term);
  }
};

/// One step of Fig. 15's negotiation sent: its kind is the message's (`step`: demote,
/// demoteack, demotenack, demoteretry).
struct demotion_sent {
  static constexpr std::string_view name = "demote";
  int camera = 0;
  task_id task = 0;
  int to = 0;
  std::string step = "demote";
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("to", to);
  }
};

struct conflict {
  static constexpr std::string_view name = "conflict";
  int camera = 0;
  task_id task = 0;
  std::vector<task_id> with_tasks;
  std::vector<int> cameras;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("with_tasks", with_tasks), f("cameras", cameras);
  }
};

struct conflict_reported {
  static constexpr std::string_view name = "conflict_reported";
  int camera = 0;
  task_id task = 0;
  std::vector<task_id> tasks;
  int to = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("tasks", tasks), f("to", to);
  }
};

struct csp_yielded {
  static constexpr std::string_view name = "csp_yielded";
  int camera = 0;
  task_id task = 0, to_task = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("to_task", to_task);
  }
};

struct csp_abandoned {
  static constexpr std::string_view name = "csp_abandoned";
  int camera = 0;
  task_id task = 0;
  std::vector<task_id> missing;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("missing", missing);
  }
};

struct csp_solved {
  static constexpr std::string_view name = "csp_solved";
  int camera = 0;
  task_id task = 0;
  std::string solver;
  std::uint64_t groups = 0, cameras = 0;
  fixed<4> weight;
  std::uint64_t nodes_explored = 0, backtracks = 0;
  bool relaxed = false;
  task_counts minima;
  bool optimal = false;
  // The problem solved and its answer, so that a reader can check it.
  std::vector<task_id> tasks;
  std::vector<int> camera_ids;
  std::vector<unsigned> min_cameras, max_cameras;
  std::vector<std::vector<fixed<6>>> relevance;
  std::vector<std::vector<int>> staying;
  std::vector<int> leaders;
  std::vector<std::vector<int>> assigned;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("solver", solver), f("groups", groups),
        f("cameras", cameras), f("weight", weight), f("nodes_explored", nodes_explored),
        f("backtracks", backtracks), f("relaxed", relaxed), f("minima", minima),
        f("optimal", optimal), f("tasks", tasks), f("camera_ids", camera_ids),
        f("min_cameras", min_cameras), f("max_cameras", max_cameras), f("relevance", relevance),
        f("fixed", staying), f("leaders", leaders), f("assigned", assigned);
  }
};

struct csp_applied {
  static constexpr std::string_view name = "csp_applied";
  int camera = 0;
  task_id task = 0;
  int solver_camera = 0;
  std::vector<int> cameras;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("solver_camera", solver_camera), f("cameras", cameras);
  }
};

}  // namespace argus::events
