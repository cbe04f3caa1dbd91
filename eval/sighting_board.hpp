#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <utility>

namespace argus::eval {

/// sensing.group_geometry: ground_truth (an instrument, simulator side): whom each group
/// member's box was on, frame by frame, so that a node looking for a task's target can be
/// pointed where the group sees her, as a perfectly learned map between views would let it.
/// Nodes write their frame of tick t during t and read the frames of t - 1, which every node
/// has finished before any turn of t begins: what a node reads is the same on any thread.
class sighting_board {
 public:
  /// Camera `camera`, in task `task`'s group (`leader` or not), had its box on `pedestrian` in
  /// the frame of `tick`.
  void put(std::int64_t tick, std::uint32_t task, int camera, bool leader, int pedestrian) {
    std::lock_guard<std::mutex> guard(mutex_);
    frames_[{tick, task}][{!leader, camera}] = pedestrian;
    // Nobody reads before t - 1 any more.
    frames_.erase(frames_.begin(), frames_.lower_bound({tick - 2, 0}));
  }

  /// Whom the group of `task` saw in the frame of `tick`: the leader's box if it had one, else
  /// the lowest-numbered member's; boxes of camera `except` are not counted.
  std::optional<int> seen(std::int64_t tick, std::uint32_t task, int except) const {
    std::lock_guard<std::mutex> guard(mutex_);
    auto frame = frames_.find({tick, task});
    if (frame == frames_.end()) return std::nullopt;
    for (const auto& [who, pedestrian] : frame->second)
      if (who.second != except) return pedestrian;
    return std::nullopt;
  }

  /// Whom camera `camera`, looking for task `task`'s target without holding her, is to be
  /// pointed at after the frame of `tick`: with `geometry`, whom another camera of the group
  /// held then; with `reappearance`, when no camera of the group held anyone then, the target
  /// herself (`target`, her id).
  std::optional<int> aim(std::int64_t tick, std::uint32_t task, int camera, bool geometry,
                         bool reappearance, std::optional<int> target) const {
    if (geometry)
      if (auto who = seen(tick, task, camera)) return who;
    if (reappearance && !seen(tick, task, no_camera)) return target;
    return std::nullopt;
  }

  /// Not a camera id: `seen(tick, task, no_camera)` counts every camera.
  static constexpr int no_camera = -1;

 private:
  mutable std::mutex mutex_;
  // (tick, task) -> (not leader, camera) -> pedestrian: leaders first, then by camera.
  std::map<std::pair<std::int64_t, std::uint32_t>, std::map<std::pair<bool, int>, int>> frames_;
};

}  // namespace argus::eval
