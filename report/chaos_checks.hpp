#pragma once

// The invariants `argus chaos` checks on each run it makes (docs/chaos.md), from the run's own
// files: events.jsonl, targets.csv and metrics.json. Plain functions of those files, so that a
// run can be checked again, or an old one checked, without running it.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "report/csv_table.hpp"
#include "report/event_log.hpp"

namespace argus::report {

/// The bounds a run must stay within.
struct chaos_bounds {
  /// Messages the nodes originate for one task in one whole simulated second.
  std::uint64_t max_messages_per_task_s = 0;
  /// The run's peak resident memory, KiB.
  long max_rss_kib = 0;
  /// After the last fault heals, a live task whose target some camera can see must have a
  /// leader within this long.
  double liveness_window_s = 10.0;
};

/// What one run showed.
struct chaos_verdict {
  /// Terms broken: a term (task, epoch, leader id; docs/protocol.md, "Terms") that has ended
  /// taken up again, so that two leaderships shared one term; or a camera's epoch in a task
  /// going back while it stayed in the task.
  std::uint64_t terms_broken = 0;
  /// Not counted as broken: a term taken up again by a camera that crashed and came back since
  /// it ended. A node keeps nothing across a crash (the paper's nodes have no stable storage),
  /// so it cannot know it led that epoch; Raft keeps its term on disk for this (docs/chaos.md).
  std::uint64_t terms_reused_after_recovery = 0;
  /// Not a fault: how often a camera took an epoch of a task that another camera then led too
  /// (two members taking over at once, say); the merge rule settles them.
  std::uint64_t same_epoch_leaderships = 0;
  /// A camera entered a group while its log still had it in another.
  std::uint64_t camera_in_two_groups = 0;
  /// Messages a node originated for a task after hearing its cancellation (metrics.json).
  std::uint64_t messages_after_cancel = 0;
  /// The most messages originated for one task in one simulated second (metrics.json).
  std::uint64_t peak_messages_per_task_s = 0;
  long peak_rss_kib = 0;
  /// Tasks live when the last fault healed (some live camera in their group, not cancelled)
  /// whose target was in the station and in some camera's reach in the window after it.
  std::size_t live_tasks = 0;
  /// Of those, the ones that had a leader at some moment of the window.
  std::size_t led_in_time = 0;
  /// Whether the run ended well and left whole files.
  bool complete = false;
  /// One line per broken invariant, for people.
  std::vector<std::string> problems;

  bool safe(const chaos_bounds& bounds) const;
  bool live() const { return led_in_time == live_tasks; }
};

/// Checks the safety invariants on a run's event log, and liveness after `healed_at_s` given
/// `targets` (targets.csv: where each task's target was, and whether any camera could see her).
chaos_verdict check_chaos_log(const event_log& events, const csv_table& targets, double healed_at_s,
                              const chaos_bounds& bounds);

/// The same on a run's folder, with metrics.json's message figures and the run's peak memory.
chaos_verdict check_chaos_run(const std::filesystem::path& run_dir, double healed_at_s,
                              const chaos_bounds& bounds, long peak_rss_kib);

}  // namespace argus::report
