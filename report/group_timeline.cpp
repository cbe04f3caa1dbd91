#include "report/group_timeline.hpp"

#include <algorithm>
#include <map>
#include <optional>

namespace argus::report {

namespace {

// Open spans while reading the log, closed into the task's lists.
struct open_task {
  task_timeline done;
  std::map<int, double> members_since;
  std::optional<std::pair<int, double>> leader_since;
  bool ended = false;
};

class timeline_builder {
 public:
  void on(const nlohmann::json& e) {
    const std::string kind = text_field(e, "kind");
    const double t = e.value("t", 0.0);
    const int task = static_cast<int>(integer_field(e, "task"));
    const int camera = static_cast<int>(integer_field(e, "camera"));
    const bool about_a_task = kind == "task_issued" || kind == "task_created" || kind == "joined" ||
                              kind == "left_task" || kind == "leader_changed" ||
                              kind == "handoff" || kind == "task_cancelled";
    if (about_a_task && task < 0) return;  // no task named: nothing to place it in
    if (kind == "task_issued") {
      auto& open = task_at(task, t);
      open.done.pedestrian = static_cast<int>(integer_field(e, "pedestrian"));
    } else if (kind == "task_created") {
      join(task_at(task, t), camera, t);
      lead(task_at(task, t), camera, t);
    } else if (kind == "joined") {
      auto& open = task_at(task, t);
      join(open, camera, t);
      const int leader = static_cast<int>(integer_field(e, "leader"));
      if (!open.leader_since && leader >= 0) lead(open, leader, t);
    } else if (kind == "left_task") {
      leave(task_at(task, t), camera, t);
    } else if (kind == "leader_changed") {
      auto& open = task_at(task, t);
      const int leader = static_cast<int>(integer_field(e, "leader", camera));
      if (!open.leader_since || open.leader_since->first != leader) lead(open, leader, t);
    } else if (kind == "handoff") {
      task_at(task, t).done.handoffs_s.push_back(t);
    } else if (kind == "task_cancelled") {
      end(task_at(task, t), t);
    } else if (kind == "fault") {
      const bool applied = !e.contains("applied") || e.value("applied", false);
      if (!applied) return;
      const std::string fault = text_field(e, "fault");
      failures_.push_back({t, camera, fault});
      if (fault == "crash" || fault == "crash_and_recover")
        for (auto& [id, open] : tasks_) leave(open, camera, t);
    } else if (kind == "node_recovered") {
      if (!e.contains("applied") || e.value("applied", false))
        failures_.push_back({t, camera, "recovered"});
    }
  }

  group_timeline finish(double end_s) {
    group_timeline out;
    out.end_s = end_s;
    for (auto& [id, open] : tasks_) {
      end(open, end_s);
      out.tasks.push_back(std::move(open.done));
    }
    out.failures = std::move(failures_);
    return out;
  }

 private:
  open_task& task_at(int task, double t) {
    auto [it, added] = tasks_.try_emplace(task);
    if (added) {
      it->second.done.task = task;
      it->second.done.start_s = t;
    }
    return it->second;
  }

  static void join(open_task& open, int camera, double t) {
    if (open.ended || camera < 0) return;
    open.members_since.try_emplace(camera, t);
  }

  static void lead(open_task& open, int camera, double t) {
    if (open.ended) return;
    close_leader(open, t);
    open.leader_since = std::pair{camera, t};
  }

  static void close_leader(open_task& open, double t) {
    if (!open.leader_since) return;
    const auto [camera, since] = *open.leader_since;
    open.done.leaders.push_back({camera, since, t});
    open.leader_since.reset();
  }

  static void leave(open_task& open, int camera, double t) {
    if (auto it = open.members_since.find(camera); it != open.members_since.end()) {
      open.done.members.push_back({camera, it->second, t});
      open.members_since.erase(it);
    }
    if (open.leader_since && open.leader_since->first == camera) close_leader(open, t);
  }

  static void end(open_task& open, double t) {
    if (open.ended) return;
    while (!open.members_since.empty()) leave(open, open.members_since.begin()->first, t);
    close_leader(open, t);
    open.done.end_s = t;
    open.ended = true;
  }

  std::map<int, open_task> tasks_;
  std::vector<failure_mark> failures_;
};

}  // namespace

group_timeline group_timeline::from(const event_log& log, double end_s) {
  timeline_builder builder;
  for (const auto& e : log.events) builder.on(e);
  return builder.finish(std::max(end_s, log.last_time_s()));
}

}  // namespace argus::report
