#include "report/group_timeline.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <variant>

#include "events/event.hpp"

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
  void on(const nlohmann::json& line) {
    const auto event = events::parse(line);
    if (!event) return;
    const double t = line.value("t", 0.0);
    std::visit([&](const auto& e) { on(e, t); }, *event);
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
  static int id(std::uint32_t task) { return static_cast<int>(task); }

  void on(const events::task_issued& e, double t) {
    task_at(id(e.task), t).done.pedestrian = e.pedestrian.value_or(-1);
  }
  void on(const events::task_created& e, double t) {
    join(task_at(id(e.task), t), e.camera, t);
    lead(task_at(id(e.task), t), e.camera, t);
  }
  void on(const events::joined& e, double t) {
    auto& open = task_at(id(e.task), t);
    join(open, e.camera, t);
    if (!open.leader_since && e.leader >= 0) lead(open, e.leader, t);
  }
  void on(const events::left_task& e, double t) { leave(task_at(id(e.task), t), e.camera, t); }
  void on(const events::leader_changed& e, double t) {
    auto& open = task_at(id(e.task), t);
    if (!open.leader_since || open.leader_since->first != e.leader) lead(open, e.leader, t);
  }
  void on(const events::handoff& e, double t) {
    task_at(id(e.task), t).done.handoffs_s.push_back(t);
  }
  void on(const events::task_cancelled& e, double t) { end(task_at(id(e.task), t), t); }
  void on(const events::fault_event& e, double t) {
    if (!e.applied) return;
    failures_.push_back({t, e.camera, e.fault});
    if (e.takes_camera_down())
      for (auto& [task, open] : tasks_) leave(open, e.camera, t);
  }
  void on(const events::node_recovered& e, double t) {
    if (e.applied) failures_.push_back({t, e.camera, "recovered"});
  }
  template <class Other>
  void on(const Other&, double) {}

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
