#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "vision/ptz_camera.hpp"

namespace argus::actors {

/// Where camera nodes leave the pose their next frame is rendered at, for the video recorder,
/// which renders every camera's view in the same phase as the nodes. A node writes in its turn
/// of clock tick t the pose it has moved to; the recorder, in its turn of tick t + 1, reads the
/// latest pose written before that tick. Each camera keeps its last two poses, so that what the
/// recorder reads never depends on whether the node has already taken its turn of the tick:
/// the video is the same on any number of threads.
class camera_pose_board {
 public:
  /// What the recorder reads: a pose and the clock tick it was written in.
  struct entry {
    std::int64_t tick = -1;
    vision::ptz_state pose;
  };

  /// Camera `camera`, in its turn of clock tick `tick`, moved to `pose`.
  void put(int camera, std::int64_t tick, const vision::ptz_state& pose) {
    std::lock_guard<std::mutex> guard(mutex_);
    auto& last = by_camera_[camera];
    if (last[1].tick == tick) {
      last[1].pose = pose;
      return;
    }
    last[0] = last[1];
    last[1] = {tick, pose};
  }

  /// The latest pose camera `camera` wrote before clock tick `tick`; none when it wrote none.
  std::optional<entry> before(int camera, std::int64_t tick) const {
    std::lock_guard<std::mutex> guard(mutex_);
    const auto it = by_camera_.find(camera);
    if (it == by_camera_.end()) return std::nullopt;
    for (auto k : {1, 0})
      if (it->second[k].tick >= 0 && it->second[k].tick < tick) return it->second[k];
    return std::nullopt;
  }

  /// Every camera's latest pose, by camera id: what a worker hands its coordinator, whose board
  /// then answers `before` as the worker's would.
  std::vector<std::pair<int, entry>> latest() const {
    std::lock_guard<std::mutex> guard(mutex_);
    std::vector<std::pair<int, entry>> out;
    out.reserve(by_camera_.size());
    for (const auto& [camera, last] : by_camera_) out.emplace_back(camera, last[1]);
    return out;
  }

 private:
  mutable std::mutex mutex_;
  std::map<int, std::array<entry, 2>> by_camera_;
};

}  // namespace argus::actors
