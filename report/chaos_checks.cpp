#include "report/chaos_checks.hpp"

#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "fmt/format.h"
#include "report/binary_file.hpp"

namespace argus::report {
namespace {

// Where each camera is, as its own events say: its task, whether it leads it, at which epoch.
struct place {
  long long task = -1;
  bool leads = false;
  long long epoch = -1;
};

class group_replay {
 public:
  explicit group_replay(chaos_verdict& out) : out_(out) {}

  void apply(const nlohmann::json& e) {
    const auto kind = text_field(e, "kind");
    const auto camera = static_cast<int>(integer_field(e, "camera", 0));
    const auto task = integer_field(e, "task");
    const auto term = integer_field(e, "term");
    const double t = e.value("t", 0.0);
    if (kind == "task_created") {
      enter(camera, task, true, term, t);
    } else if (kind == "joined") {
      const auto leader = static_cast<int>(integer_field(e, "leader"));
      enter(camera, task, leader == camera, term, t);
    } else if (kind == "leader_changed") {
      const auto leader = static_cast<int>(integer_field(e, "leader"));
      auto it = places_.find(camera);
      if (it == places_.end() || it->second.task != task) {
        ++out_.camera_in_two_groups;
        problem(t, fmt::format("camera {} changed leader in task {} while its log has it in {}",
                               camera, task, it == places_.end() ? -1 : it->second.task));
        enter(camera, task, leader == camera, term, t);
        return;
      }
      if (leader == camera && it->second.leads && term == it->second.epoch) return;  // the same
      if (term < it->second.epoch) {
        ++out_.terms_broken;
        problem(t, fmt::format("camera {}'s epoch in task {} went back from {} to {}", camera, task,
                               it->second.epoch, term));
      }
      end_term(camera);
      it->second.leads = leader == camera;
      it->second.epoch = term;
      if (leader == camera) start_term(camera, t);
    } else if (kind == "handoff") {
      end_term(camera);
      if (auto it = places_.find(camera); it != places_.end()) it->second.leads = false;
    } else if (kind == "left_task") {
      leave(camera);
    } else if (kind == "fault") {
      if (e.value("applied", false) &&
          (text_field(e, "fault") == "crash" || text_field(e, "fault") == "crash_and_recover")) {
        leave(camera);
        ++incarnation_[camera];  // it comes back with nothing in memory
      }
    } else if (kind == "task_cancelled") {
      cancelled_.insert(task);
    }
  }

  // Tasks some camera is in, and whether any leads each.
  std::map<long long, bool> tasks() const {
    std::map<long long, bool> out;
    for (const auto& [camera, p] : places_) out[p.task] = out[p.task] || p.leads;
    return out;
  }
  bool cancelled(long long task) const { return cancelled_.count(task) != 0; }

 private:
  void enter(int camera, long long task, bool leads, long long epoch, double t) {
    if (auto it = places_.find(camera); it != places_.end() && it->second.task != task) {
      ++out_.camera_in_two_groups;
      problem(t, fmt::format("camera {} entered task {} while its log has it in task {}", camera,
                             task, it->second.task));
    }
    leave(camera);
    places_[camera] = {task, leads, epoch};
    if (leads) start_term(camera, t);
  }

  void leave(int camera) {
    end_term(camera);
    places_.erase(camera);
  }

  // A leadership ends: its term may never be taken again.
  void end_term(int camera) {
    auto it = places_.find(camera);
    if (it == places_.end() || !it->second.leads) return;
    ended_[{it->second.task, it->second.epoch, camera}] = incarnation_[camera];
  }

  void start_term(int camera, double t) {
    const auto& p = places_.at(camera);
    if (p.epoch < 0) return;
    if (auto ended = ended_.find({p.task, p.epoch, camera}); ended != ended_.end()) {
      if (ended->second == incarnation_[camera]) {
        ++out_.terms_broken;
        problem(t, fmt::format("camera {} took up task {}'s term (epoch {}) again after it ended",
                               camera, p.task, p.epoch));
      } else {
        ++out_.terms_reused_after_recovery;
      }
    }
    for (const auto& [other, q] : places_)
      if (other != camera && q.leads && q.task == p.task && q.epoch == p.epoch)
        ++out_.same_epoch_leaderships;
  }

  void problem(double t, std::string what) {
    if (out_.problems.size() < 20) out_.problems.push_back(fmt::format("t={:.2f} s: {}", t, what));
  }

  chaos_verdict& out_;
  std::map<int, place> places_;
  std::map<std::tuple<long long, long long, int>, int> ended_;  // term -> the incarnation
  std::map<int, int> incarnation_;
  std::set<long long> cancelled_;
};

// Tasks whose target was in the station and within some camera's reach in [from, to].
std::set<long long> seen_tasks(const csv_table& targets, double from, double to) {
  std::set<long long> out;
  const auto t = targets.column("t"), task = targets.column("task"),
             present = targets.column("present"), reachable = targets.column("reachable");
  if (!t || !task || !present || !reachable) return out;
  for (const auto& row : targets.rows()) {
    const double at = csv_table::number(row, *t, -1.0);
    if (at < from || at > to) continue;
    if (csv_table::number(row, *present, 0.0) > 0.0 &&
        csv_table::number(row, *reachable, 0.0) > 0.0)
      out.insert(static_cast<long long>(csv_table::number(row, *task, -1.0)));
  }
  return out;
}

}  // namespace

bool chaos_verdict::safe(const chaos_bounds& bounds) const {
  return complete && terms_broken == 0 && camera_in_two_groups == 0 && messages_after_cancel == 0 &&
         (bounds.max_messages_per_task_s == 0 ||
          peak_messages_per_task_s <= bounds.max_messages_per_task_s) &&
         (bounds.max_rss_kib == 0 || peak_rss_kib <= bounds.max_rss_kib);
}

chaos_verdict check_chaos_log(const event_log& events, const csv_table& targets, double healed_at_s,
                              const chaos_bounds& bounds) {
  chaos_verdict out;
  group_replay replay(out);
  const double window_end = healed_at_s + bounds.liveness_window_s;
  const auto seen = seen_tasks(targets, healed_at_s, window_end);
  std::optional<std::map<long long, bool>> at_heal;
  std::set<long long> led;
  auto note_leaders = [&] {
    for (const auto& [task, leads] : replay.tasks())
      if (leads) led.insert(task);
  };
  for (const auto& e : events.events) {
    const double t = e.value("t", 0.0);
    if (!at_heal && t > healed_at_s) {
      at_heal = replay.tasks();
      note_leaders();
    }
    replay.apply(e);
    if (at_heal && t <= window_end) note_leaders();
  }
  if (!at_heal) {  // nothing logged after the heal: the groups stand as they were
    at_heal = replay.tasks();
    note_leaders();
  }
  if (at_heal) {
    for (const auto& [task, leads] : *at_heal) {
      if (replay.cancelled(task) || seen.count(task) == 0) continue;
      ++out.live_tasks;
      if (led.count(task) != 0) {
        ++out.led_in_time;
      } else if (out.problems.size() < 20) {
        out.problems.push_back(fmt::format(
            "task {} had no leader from {:.1f} s to {:.1f} s though her camera could see her", task,
            healed_at_s, window_end));
      }
    }
  }
  return out;
}

chaos_verdict check_chaos_run(const std::filesystem::path& run_dir, double healed_at_s,
                              const chaos_bounds& bounds, long peak_rss_kib) {
  const auto events = event_log::read(run_dir / "events.jsonl");
  const auto targets = csv_table::read(run_dir / "targets.csv");
  const auto metrics = read_json(run_dir / "metrics.json");
  chaos_verdict out = check_chaos_log(
      events.value_or(event_log{}), targets.value_or(csv_table::parse("t\n")), healed_at_s, bounds);
  out.peak_rss_kib = peak_rss_kib;
  out.complete = events.has_value() && metrics.is_object() && metrics.contains("summary");
  if (!out.complete) {
    out.problems.push_back("the run left no whole events.jsonl and metrics.json");
    return out;
  }
  const auto& summary = metrics["summary"];
  out.messages_after_cancel = summary.value("messages_after_cancel", std::uint64_t{0});
  out.peak_messages_per_task_s = summary.value("peak_messages_per_task_s", std::uint64_t{0});
  if (out.messages_after_cancel > 0)
    out.problems.push_back(
        fmt::format("{} messages sent for a task after its cancellation reached the sender",
                    out.messages_after_cancel));
  if (bounds.max_messages_per_task_s > 0 &&
      out.peak_messages_per_task_s > bounds.max_messages_per_task_s)
    out.problems.push_back(fmt::format("{} messages for one task in one second (bound {})",
                                       out.peak_messages_per_task_s,
                                       bounds.max_messages_per_task_s));
  if (bounds.max_rss_kib > 0 && peak_rss_kib > bounds.max_rss_kib)
    out.problems.push_back(fmt::format("peak memory {} MiB (bound {} MiB)", peak_rss_kib / 1024,
                                       bounds.max_rss_kib / 1024));
  return out;
}

}  // namespace argus::report
