#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace argus::apps {

/// The sweep's progress on stderr: on a terminal one self-overwriting bar (runs done of the
/// total, failures, ETA from this session's pace), elsewhere one line per finished run, so a
/// log file records each. Runs found done from an earlier session count as done but not in
/// the pace.
class sweep_progress {
 public:
  sweep_progress(std::size_t total, std::size_t done_before, bool terminal);

  /// One run ended with `exit_status` after `wall_s` seconds.
  void run_ended(const std::string& id, int exit_status, double wall_s);

  /// Ends the bar's line.
  void finish();

 private:
  std::string bar() const;

  std::size_t total_;
  std::size_t done_;
  std::size_t done_now_ = 0;
  std::size_t failed_ = 0;
  bool terminal_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

}  // namespace argus::apps
