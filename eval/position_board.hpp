#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <utility>

#include "vision/floor_estimate.hpp"

namespace argus::eval {

/// sensing.group_geometry: calibrated: where each task's group members' calibrated cameras put
/// their boxes on the floor, frame by frame. A board, not messages: every member's estimate
/// reaches every node of the run in the next frame, never lost or late, so what it measures
/// is an upper bound on what calibrated cameras sharing their estimates could do. Nodes write their
/// frame of tick t during t and read frames up to t - 1, which every node has finished before any
/// turn of t begins: what a node reads is the same on any thread.
class position_board {
 public:
  void put(std::uint32_t task, int camera, bool leader, const vision::floor_estimate& e) {
    std::lock_guard<std::mutex> guard(mutex_);
    auto& frames = tasks_[task];
    frames[e.tick][{!leader, camera}] = e;
    frames.erase(frames.begin(), frames.lower_bound(e.tick - kept_ticks));
  }

  /// The group's latest estimate of task `task`'s target in a frame up to `tick`: the leader's
  /// if it had one in that frame, else the lowest-numbered member's.
  std::optional<vision::floor_estimate> latest(std::uint32_t task, std::int64_t tick) const {
    std::lock_guard<std::mutex> guard(mutex_);
    auto t = tasks_.find(task);
    if (t == tasks_.end()) return std::nullopt;
    auto after = t->second.upper_bound(tick);
    if (after == t->second.begin()) return std::nullopt;
    --after;
    return after->second.begin()->second;
  }

  /// How many ticks of estimates a task keeps (two minutes at 15 frames a second): far more
  /// than any node trusts one for.
  static constexpr std::int64_t kept_ticks = 1800;

 private:
  mutable std::mutex mutex_;
  std::map<std::uint32_t,
           std::map<std::int64_t, std::map<std::pair<bool, int>, vision::floor_estimate>>>
      tasks_;
};

}  // namespace argus::eval
