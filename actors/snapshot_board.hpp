#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "world/snapshot.hpp"

namespace argus::actors {

/// The world's latest snapshot, where camera nodes read it to sense. The world coordinator
/// publishes in phase network and camera nodes read in phase cameras of the same tick; the
/// clock's phase barrier orders every read after that tick's publication and before the next,
/// so what a node reads depends on the tick alone, never on threads. The lock only makes the
/// hand-over of the pointer itself safe.
///
/// Why not mail: a camera that recovers from a crash is a new actor, and the coordinator's
/// list of observers is fixed when the run starts; every camera, old or new, finds the board.
class snapshot_board {
 public:
  /// Called with every publication, in the order added (the evaluation samples the targets,
  /// the live console shows it).
  using subscriber = std::function<void(const std::shared_ptr<const world::snapshot>&)>;

  /// Publishes `frame` (phase network).
  void publish(std::shared_ptr<const world::snapshot> frame) {
    for (const auto& s : subscribers_) s(frame);
    std::lock_guard<std::mutex> guard(mutex_);
    latest_ = std::move(frame);
  }
  /// Adds a subscriber (before the run starts).
  void subscribe(subscriber s) { subscribers_.push_back(std::move(s)); }
  /// The latest snapshot (phase cameras); null before the first.
  std::shared_ptr<const world::snapshot> latest() const {
    std::lock_guard<std::mutex> guard(mutex_);
    return latest_;
  }

 private:
  std::vector<subscriber> subscribers_;
  mutable std::mutex mutex_;
  std::shared_ptr<const world::snapshot> latest_;
};

}  // namespace argus::actors
