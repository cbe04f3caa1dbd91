#include "eval/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "config/enum_names.hpp"
#include "eval/reachability.hpp"
#include "fmt/format.h"
#include "nlohmann/json.hpp"
#include "world/station.hpp"

namespace argus::eval {
namespace {

// The looks of one task in one tick: (camera, look).
using tick_looks = std::vector<std::pair<int, const look_record*>>;

// The kinds the metrics read: every other line is skipped before it is parsed.
bool is_metric_kind(std::string_view kind) {
  for (std::string_view k : {events::handoff::name, events::leader_changed::name,
                             events::conflict::name, events::fault_event::name})
    if (kind == k) return true;
  return false;
}

std::string_view name_of(target_choice by) {
  switch (by) {
    case target_choice::pedestrian:
      return "pedestrian";
    case target_choice::pixel:
      return "pixel";
    case target_choice::first_to_enter:
      return "first_to_enter";
  }
  return "pedestrian";
}

// What the run recorded, indexed for the per-task passes.
struct indexed_log {
  std::map<std::uint32_t, std::map<std::int64_t, tick_looks>> looks;   // task -> tick -> looks
  std::map<int, std::vector<std::int64_t>> alive;                      // camera -> its ticks
  std::map<std::uint32_t, std::vector<const target_sample*>> samples;  // task -> by tick

  explicit indexed_log(const observation_log::contents& log) {
    for (const auto& [camera, frames] : log.frames)
      for (const auto& f : frames) {
        alive[camera].push_back(f.tick);
        for (const auto& l : f.looks) looks[l.task][f.tick].emplace_back(camera, &l);
      }
    for (const auto& s : log.samples) samples[s.task].push_back(&s);
  }

  const tick_looks* at(std::uint32_t task, std::int64_t tick) const {
    auto t = looks.find(task);
    if (t == looks.end()) return nullptr;
    auto k = t->second.find(tick);
    return k == t->second.end() ? nullptr : &k->second;
  }

  bool is_alive(int camera, std::int64_t tick) const {
    auto it = alive.find(camera);
    return it != alive.end() && std::binary_search(it->second.begin(), it->second.end(), tick);
  }
};

// The camera observing the target in this tick: the previous observer if it still does (a
// handoff is a change of observer), else the lowest id that does; -1 when nobody does.
int observer_of(const tick_looks* looks, int previous) {
  if (looks == nullptr) return -1;
  int lowest = -1;
  for (const auto& [camera, look] : *looks) {
    if (!look->observed) continue;
    if (camera == previous) return camera;
    if (lowest < 0 || camera < lowest) lowest = camera;
  }
  return lowest;
}

// Adds an uncovered tick to the first cause that holds in it (uncovered_time's order).
void count_uncovered(const tick_looks* looks, int pedestrian, uncovered_time& counts) {
  bool off_her = false, other = false, background = false, lost = false;
  if (looks != nullptr)
    for (const auto& [camera, look] : *looks) {
      if (!look->found)
        lost = true;
      else if (look->truth == pedestrian)
        off_her = true;
      else if (look->truth >= 0)
        other = true;
      else
        background = true;
    }
  auto& cause = off_her      ? counts.off_her
                : other      ? counts.other_person
                : background ? counts.background
                : lost       ? counts.lost
                             : counts.no_camera;
  cause += 1.0;
}

bool any_reaches(const config::scenario& scenario, const world::station& station,
                 const indexed_log& index, const target_sample& s) {
  for (const auto& camera : scenario.cameras) {
    if (!index.is_alive(camera.id, s.tick)) continue;
    if (reachable(camera, station, world::vec2{s.x_m, s.y_m}, s.height_m)) return true;
  }
  return false;
}

// Group size (cameras performing the task), correct identity and identity switches over
// [start, end).
void group_figures(const indexed_log& index, task_metrics& m, std::int64_t start, std::int64_t end,
                   double tick_s) {
  std::map<int, int> last_truth;
  std::uint64_t found = 0;
  std::uint64_t correct = 0;
  double size_sum = 0.0;
  int last_size = -1;
  for (std::int64_t tick = start; tick < end; ++tick) {
    const auto* looks = index.at(m.task, tick);
    const int size = looks ? static_cast<int>(looks->size()) : 0;
    size_sum += size;
    m.group_size_max = std::max(m.group_size_max, size);
    if (size != last_size) m.group_size_series.emplace_back(tick * tick_s, size);
    last_size = size;
    if (looks == nullptr) continue;
    for (const auto& [camera, look] : *looks) {
      if (!look->found) continue;
      ++found;
      if (look->truth == m.pedestrian) ++correct;
      if (look->truth < 0) continue;
      auto [it, fresh] = last_truth.emplace(camera, look->truth);
      if (!fresh && it->second != look->truth) {
        ++m.identity_switches;
        it->second = look->truth;
      }
    }
  }
  if (end > start) m.group_size_mean = size_sum / static_cast<double>(end - start);
  if (found > 0) m.correct_identity = static_cast<double>(correct) / static_cast<double>(found);
}

void event_figures(const std::vector<logged_event>& events, const indexed_log& index,
                   const std::vector<std::int64_t>& observed_ticks, task_metrics& m,
                   std::int64_t start, std::int64_t end, double tick_s) {
  for (const auto& e : events) {
    if (e.tick < start || e.tick >= end) continue;
    if (const auto* h = std::get_if<events::handoff>(&e.event); h && h->task == m.task)
      ++m.handoffs;
    if (const auto* l = std::get_if<events::leader_changed>(&e.event); l && l->task == m.task)
      ++m.leader_changes;
    if (const auto* c = std::get_if<events::conflict>(&e.event);
        c && (c->task == m.task ||
              std::find(c->with_tasks.begin(), c->with_tasks.end(), m.task) != c->with_tasks.end()))
      ++m.csp_invocations;
    const auto* f = std::get_if<events::fault_event>(&e.event);
    if (f == nullptr || !f->takes_camera_down()) continue;
    // A failure counts for the task when the camera was in its group just before.
    const auto* before = index.at(m.task, e.tick - 1);
    if (before == nullptr || std::none_of(before->begin(), before->end(),
                                          [&](const auto& l) { return l.first == f->camera; }))
      continue;
    recovery r{f->camera, e.t, std::nullopt};
    auto next = std::upper_bound(observed_ticks.begin(), observed_ticks.end(), e.tick);
    if (next != observed_ticks.end()) r.recovered_after_s = (*next - e.tick) * tick_s;
    m.failure_recoveries.push_back(r);
  }
}

}  // namespace

std::vector<logged_event> read_events(const std::filesystem::path& events_jsonl) {
  std::ifstream in(events_jsonl);
  if (!in) throw std::runtime_error(fmt::format("cannot read {}", events_jsonl.string()));
  std::vector<logged_event> out;
  std::string line;
  while (std::getline(in, line)) {
    // Most lines are of other kinds: look before parsing.
    const auto at = line.find(R"("kind":")");
    if (at == std::string::npos) continue;
    const auto end = line.find('"', at + 8);
    if (!is_metric_kind(line.substr(at + 8, end - at - 8))) continue;
    const auto j = nlohmann::json::parse(line);
    auto event = events::parse(j);
    if (!event) continue;  // a line of its kind without its members: nothing to count
    out.push_back({j.value("tick", std::int64_t{0}), j.value("t", 0.0), std::move(*event)});
  }
  return out;
}

evaluation evaluate(const config::scenario& scenario, const world::station& station,
                    const observation_log::contents& log, const std::vector<logged_event>& events,
                    std::int64_t end_tick) {
  const double tick_s = scenario.run.tick.count();
  const indexed_log index(log);
  evaluation out;
  for (const auto& origin : log.origins) {
    task_metrics m;
    m.task = origin.task;
    m.pedestrian = origin.pedestrian;
    m.camera = origin.camera;
    m.how = std::string(name_of(origin.by));
    const std::int64_t start = origin.tick;
    std::int64_t end = end_tick;
    m.end_reason = "run_end";
    if (auto c = log.cancels.find(origin.task); c != log.cancels.end() && c->second < end) {
      end = c->second;
      m.end_reason = "cancelled";
    }
    std::vector<std::int64_t> observed_ticks;
    std::int64_t present = 0, observed = 0, observed_iou50 = 0, reachable_ticks = 0;
    int observer = -1;
    std::int64_t last_observed = -1;
    if (auto it = index.samples.find(origin.task); it != index.samples.end()) {
      for (const auto* s : it->second) {
        if (s->tick < start || s->tick >= end) continue;
        target_row row{*s, false, -1};
        if (!s->present) {
          end = s->tick;
          m.end_reason = "left_station";
          out.targets.push_back(row);
          break;
        }
        ++present;
        const auto* looks = index.at(origin.task, s->tick);
        const int now = observer_of(looks, observer);
        if (now >= 0) {
          ++observed;
          observed_ticks.push_back(s->tick);
          if (observer >= 0 && now != observer) {
            ++m.observation_handoffs;
            m.handoff_gaps_s.push_back((s->tick - last_observed - 1) * tick_s);
          }
          observer = now;
          last_observed = s->tick;
        } else {
          count_uncovered(looks, origin.pedestrian, m.uncovered);
        }
        if (looks && std::any_of(looks->begin(), looks->end(), [&](const auto& l) {
              return l.second->truth == origin.pedestrian && l.second->iou >= 0.5;
            }))
          ++observed_iou50;
        row.reachable = any_reaches(scenario, station, index, *s);
        if (row.reachable) ++reachable_ticks;
        row.observed_by = now;
        out.targets.push_back(row);
      }
    }
    m.start_s = start * tick_s;
    m.end_s = end * tick_s;
    m.time_in_station_s = present * tick_s;
    if (present > 0) {
      m.coverage = static_cast<double>(observed) / present;
      m.coverage_iou50 = static_cast<double>(observed_iou50) / present;
      m.oracle_bound = static_cast<double>(reachable_ticks) / present;
      for (const auto& [name, share] : uncovered_causes)
        m.uncovered.*share /= static_cast<double>(present);
    }
    if (m.oracle_bound > 0.0) m.coverage_of_oracle = m.coverage / m.oracle_bound;
    group_figures(index, m, start, end, tick_s);
    event_figures(events, index, observed_ticks, m, start, end, tick_s);
    for (const auto& [key, count] : log.sent)
      if (key.first == origin.task) m.messages_by_kind[key.second] = count;
    if (auto it = log.sent_by_tick.find(origin.task); it != log.sent_by_tick.end()) {
      // Whole simulated seconds from the run's start: second k holds ticks [k/tick_s, ...).
      std::map<std::int64_t, std::uint64_t> per_second;
      for (const auto& [tick, count] : it->second)
        per_second[static_cast<std::int64_t>(
            std::floor(static_cast<double>(tick) * tick_s + 1e-9))] += count;
      for (const auto& [second, count] : per_second)
        m.peak_messages_per_s = std::max(m.peak_messages_per_s, count);
    }
    for (const auto& [key, count] : log.sent_after_cancel)
      if (key.first == origin.task) {
        m.messages_after_cancel += count;
        m.messages_after_cancel_by_kind[key.second] = count;
      }
    out.tasks.push_back(std::move(m));
  }
  return out;
}

namespace {

nlohmann::json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json task_json(const task_metrics& m) {
  nlohmann::json recoveries = nlohmann::json::array();
  for (const auto& r : m.failure_recoveries)
    recoveries.push_back({{"camera", r.camera},
                          {"at_s", r.at_s},
                          {"recovered_after_s", optional_number(r.recovered_after_s)}});
  nlohmann::json series = nlohmann::json::array();
  for (const auto& [t, size] : m.group_size_series) series.push_back({t, size});
  std::uint64_t messages = 0;
  for (const auto& [kind, count] : m.messages_by_kind) messages += count;
  nlohmann::json uncovered = nlohmann::json::object();
  for (const auto& [name, share] : uncovered_causes)
    uncovered[std::string(name)] = m.uncovered.*share;
  return {
      {"task", m.task},
      {"pedestrian", m.pedestrian},
      {"camera", m.camera},
      {"how", m.how},
      {"start_s", m.start_s},
      {"end_s", m.end_s},
      {"end_reason", m.end_reason},
      {"time_in_station_s", m.time_in_station_s},
      {"coverage", m.coverage},
      {"coverage_iou50", m.coverage_iou50},
      {"uncovered", uncovered},
      {"correct_identity", optional_number(m.correct_identity)},
      {"oracle_bound", m.oracle_bound},
      {"coverage_of_oracle", optional_number(m.coverage_of_oracle)},
      {"handoffs", m.handoffs},
      {"observation_handoffs", m.observation_handoffs},
      {"handoff_gaps_s", m.handoff_gaps_s},
      {"identity_switches", m.identity_switches},
      {"group_size", {{"mean", m.group_size_mean}, {"max", m.group_size_max}, {"series", series}}},
      {"leader_changes", m.leader_changes},
      {"messages_by_kind", m.messages_by_kind},
      {"messages", messages},
      {"peak_messages_per_s", m.peak_messages_per_s},
      {"messages_after_cancel", m.messages_after_cancel},
      {"messages_after_cancel_by_kind", m.messages_after_cancel_by_kind},
      {"csp_invocations", m.csp_invocations},
      {"failure_recoveries", recoveries}};
}

// The mean of `pick` over tasks where it is defined, or null.
template <class Pick>
nlohmann::json mean_over(const std::vector<task_metrics>& tasks, Pick pick) {
  double sum = 0.0;
  int n = 0;
  for (const auto& m : tasks)
    if (auto v = pick(m)) {
      sum += *v;
      ++n;
    }
  return n > 0 ? nlohmann::json(sum / n) : nlohmann::json(nullptr);
}

// The least-covered task's coverage: a run serves all its tasks (Fig. 19) only when this does.
nlohmann::json min_coverage(const std::vector<task_metrics>& tasks) {
  if (tasks.empty()) return nullptr;
  double least = tasks.front().coverage;
  for (const auto& m : tasks) least = std::min(least, m.coverage);
  return least;
}

}  // namespace

nlohmann::json metrics_json(const config::scenario& scenario, const evaluation& result,
                            double wall_seconds, double virtual_seconds) {
  nlohmann::json tasks = nlohmann::json::array();
  std::uint64_t handoffs = 0, switches = 0, messages = 0, peak = 0, after_cancel = 0;
  for (const auto& m : result.tasks) {
    tasks.push_back(task_json(m));
    handoffs += m.observation_handoffs;
    switches += m.identity_switches;
    for (const auto& [kind, count] : m.messages_by_kind) messages += count;
    peak = std::max(peak, m.peak_messages_per_s);
    after_cancel += m.messages_after_cancel;
  }
  const auto& t = result.tasks;
  nlohmann::json summary = {
      {"tasks", t.size()},
      {"mean_coverage",
       mean_over(t, [](const auto& m) { return std::optional<double>(m.coverage); })},
      {"mean_coverage_iou50",
       mean_over(t, [](const auto& m) { return std::optional<double>(m.coverage_iou50); })},
      {"min_coverage", min_coverage(t)},
      {"mean_oracle_bound",
       mean_over(t, [](const auto& m) { return std::optional<double>(m.oracle_bound); })},
      {"mean_coverage_of_oracle", mean_over(t, [](const auto& m) { return m.coverage_of_oracle; })},
      {"mean_correct_identity", mean_over(t, [](const auto& m) { return m.correct_identity; })},
      {"handoffs", handoffs},
      {"identity_switches", switches},
      {"messages", messages},
      {"peak_messages_per_task_s", peak},
      {"messages_after_cancel", after_cancel},
      {"wall_seconds", wall_seconds},
      {"speed_ratio", wall_seconds > 0.0 ? nlohmann::json(virtual_seconds / wall_seconds)
                                         : nlohmann::json(nullptr)}};
  for (const auto& [name, share] : uncovered_causes)
    summary["mean_uncovered_" + std::string(name)] =
        mean_over(t, [share](const auto& m) { return std::optional<double>(m.uncovered.*share); });
  return {{"definitions", "docs/metrics.md"},
          {"scenario", scenario.name},
          {"seed", scenario.run.seed},
          {"strategy", scenario.controller.strategy},
          {"sensing", std::string(config::yaml_name(scenario.sensing.mode))},
          {"duration_s", virtual_seconds},
          {"tasks", tasks},
          {"summary", summary}};
}

}  // namespace argus::eval
