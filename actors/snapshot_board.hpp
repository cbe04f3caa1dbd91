#pragma once

#include <memory>
#include <mutex>

#include "eval/observation_log.hpp"
#include "live/console_state.hpp"
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
  /// Publishes `frame` (phase network), and samples the tasks' targets in it when the run is
  /// evaluated.
  void publish(std::shared_ptr<const world::snapshot> frame) {
    if (log_) sample_targets(*log_, *frame);
    if (console_) console_->publish_snapshot(frame);
    std::lock_guard<std::mutex> guard(mutex_);
    latest_ = std::move(frame);
  }
  /// Where publications record the targets' true states (before the run starts).
  void record_targets_in(std::shared_ptr<eval::observation_log> log) { log_ = std::move(log); }
  /// Where publications also go to be shown live (argus serve; before the run starts).
  void show_on(std::shared_ptr<live::console_state> console) { console_ = std::move(console); }
  /// The latest snapshot (phase cameras); null before the first.
  std::shared_ptr<const world::snapshot> latest() const {
    std::lock_guard<std::mutex> guard(mutex_);
    return latest_;
  }

 private:
  static void sample_targets(eval::observation_log& log, const world::snapshot& frame) {
    std::vector<eval::target_sample> samples;
    for (const auto& o : log.origins()) {
      eval::target_sample s{static_cast<std::int64_t>(frame.tick()), o.task, o.pedestrian};
      if (const auto* who = frame.find(o.pedestrian)) {
        s.x_m = who->position.x();
        s.y_m = who->position.y();
        s.height_m = who->look.height_m;
        s.present = true;
      }
      samples.push_back(s);
    }
    if (!samples.empty()) log.add_samples(std::move(samples));
  }

  std::shared_ptr<eval::observation_log> log_;
  std::shared_ptr<live::console_state> console_;
  mutable std::mutex mutex_;
  std::shared_ptr<const world::snapshot> latest_;
};

}  // namespace argus::actors
