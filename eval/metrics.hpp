#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "config/scenario.hpp"
#include "eval/observation_log.hpp"
#include "events/event.hpp"
#include "nlohmann/json_fwd.hpp"

namespace argus::world {
class station;
}

namespace argus::eval {

/// The events of a run the metrics read (handoffs, leader changes, conflicts, faults), from
/// `events.jsonl`.
struct logged_event {
  std::int64_t tick = 0;
  double t = 0.0;
  events::event event;
};

/// Reads the kinds of `events.jsonl` the metrics need (handoff, leader_changed, conflict,
/// fault), as the log's event structs.
std::vector<logged_event> read_events(const std::filesystem::path& events_jsonl);

/// A camera failure and how long the task took to observe its target again.
struct recovery {
  int camera = 0;
  double at_s = 0.0;
  std::optional<double> recovered_after_s;
};

/// Why she was not covered, as fractions of her time in the station (docs/metrics.md): in each
/// uncovered tick the first of these that holds. With coverage they sum to 1.
struct uncovered_time {
  /// A member's box is labelled her but does not contain her (it sits on part of her).
  double off_her = 0.0;
  /// A member's box holds someone else.
  double other_person = 0.0;
  /// A member's box holds nobody: floor, wall, furniture.
  double background = 0.0;
  /// The group's members have lost the track.
  double lost = 0.0;
  /// No camera performs the task.
  double no_camera = 0.0;
};

/// The causes by their names in metrics.json, in uncovered_time's order.
inline constexpr std::array<std::pair<std::string_view, double uncovered_time::*>, 5>
    uncovered_causes{{{"off_her", &uncovered_time::off_her},
                      {"other_person", &uncovered_time::other_person},
                      {"background", &uncovered_time::background},
                      {"lost", &uncovered_time::lost},
                      {"no_camera", &uncovered_time::no_camera}}};

/// One task's figures (docs/metrics.md defines each).
struct task_metrics {
  std::uint32_t task = 0;
  int pedestrian = 0;
  int camera = 0;
  std::string how;
  double start_s = 0.0;
  double end_s = 0.0;
  std::string end_reason;  // left_station | cancelled | run_end
  double time_in_station_s = 0.0;
  double coverage = 0.0;
  double coverage_iou50 = 0.0;
  uncovered_time uncovered;
  std::optional<double> correct_identity;
  double oracle_bound = 0.0;
  std::optional<double> coverage_of_oracle;
  int handoffs = 0;
  int observation_handoffs = 0;
  std::vector<double> handoff_gaps_s;
  int identity_switches = 0;
  double group_size_mean = 0.0;
  int group_size_max = 0;
  std::vector<std::pair<double, int>> group_size_series;  // (t, size) at each change
  int leader_changes = 0;
  std::map<std::string, std::uint64_t> messages_by_kind;
  /// The most messages its nodes originated for it in one whole simulated second.
  std::uint64_t peak_messages_per_s = 0;
  /// Messages originated for it by nodes that had heard its cancellation (none expected).
  std::uint64_t messages_after_cancel = 0;
  std::map<std::string, std::uint64_t> messages_after_cancel_by_kind;
  int csp_invocations = 0;
  std::vector<recovery> failure_recoveries;
};

/// A target's state in one tick with what the evaluation made of it (targets.csv).
struct target_row {
  target_sample sample;
  bool reachable = false;
  int observed_by = -1;
};

/// Everything the evaluation computed.
struct evaluation {
  std::vector<task_metrics> tasks;
  std::vector<target_row> targets;
};

/// Computes the metrics of every task from what the run recorded.
evaluation evaluate(const config::scenario& scenario, const world::station& station,
                    const observation_log::contents& log, const std::vector<logged_event>& events,
                    std::int64_t end_tick);

/// `metrics.json`'s content: the tasks and their summary.
nlohmann::json metrics_json(const config::scenario& scenario, const evaluation& result,
                            double wall_seconds, double virtual_seconds);

}  // namespace argus::eval
