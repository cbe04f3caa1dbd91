#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <set>

#include "actors/node_observer.hpp"
#include "actors/wire_live.hpp"

namespace argus::actors {

/// A worker's cameras as a live run's console shows them, kept until the coordinator gathers
/// them (`argus serve --workers`): it passes every call on to the worker's own observer, and keeps
/// each camera's latest turn (its pose, its frame as JPEG, the tracker's boxes) and the traffic
/// counts. Cameras call it from their turns, on any thread; each encodes its own frame there.
class display_relay final : public node_observer {
 public:
  explicit display_relay(std::shared_ptr<node_observer> inner);

  void traffic(int camera, std::uint64_t sent, std::uint64_t received) override;
  void picked(const task_pick& pick) override;
  void turn_done(int camera, std::int64_t tick, const vision::ptz_state& pose, const cv::Mat& image,
                 const std::vector<controller::look_result>& looks) override;

  /// What was kept since the last call, by camera, and the traffic since; then forgets it.
  live_display take();

  /// From now on, only these cameras' frames are encoded and kept (`display_watch`); the others
  /// show their poses only. None at first: no page watches yet.
  void watch(const std::vector<int>& cameras);

 private:
  std::shared_ptr<node_observer> inner_;
  std::mutex mutex_;
  std::map<int, camera_display> latest_;
  std::set<int> watched_;
  std::uint64_t sent_ = 0;
  std::uint64_t received_ = 0;
};

}  // namespace argus::actors
