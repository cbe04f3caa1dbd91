#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "eval/records.hpp"

namespace argus::world {
class snapshot;
}  // namespace argus::world

namespace argus::eval {

/// Where a run's nodes and world leave what the evaluation needs. Camera nodes add their own
/// frames in phase cameras; the world's publication adds the targets' samples in phase
/// network; the clock's phase barriers order every tick's writes, so the content depends on
/// the tick alone, never on threads. The lock only protects the containers. Each camera's
/// frames are kept apart, so the order cameras of one tick write in does not matter either.
class observation_log {
 public:
  /// Whether frames carry everyone visible (MOTChallenge ground truth; costs a visibility
  /// pass per camera per frame).
  explicit observation_log(bool with_visible = false) : with_visible_(with_visible) {}

  bool with_visible() const noexcept { return with_visible_; }

  void add_frame(camera_frame frame);
  /// A task's target became known (operator's camera, phase cameras).
  void add_origin(const task_origin& origin);
  /// The operator cancelled `task` at `tick`.
  void add_cancel(std::uint32_t task, std::int64_t tick);
  /// The pedestrian a task follows, if known.
  std::optional<int> target_of(std::uint32_t task) const;
  /// Tasks and their targets, for the world to sample.
  std::vector<task_origin> origins() const;
  void add_samples(std::vector<target_sample> samples);
  /// The cameras that recorded a frame in `tick` (once that tick's camera phase is over).
  std::set<int> cameras_alive(std::int64_t tick) const;
  /// A message a node originated at `tick` for `task`.
  void add_sent(std::uint32_t task, std::string_view kind, std::int64_t tick);
  /// A message a node originated for `task` after it had heard the task's cancellation
  /// (anything but the `cancel` it spreads): the protocol must send none.
  void add_sent_after_cancel(std::uint32_t task, std::string_view kind);

  /// A pick that another process's camera made (a distributed run's mirror of the picks,
  /// docs/distributed.md); ignored when the task's target is known already.
  void add_origin_if_new(const task_origin& origin);
  /// Everything recorded, once the run is over.
  struct contents {
    std::map<int, std::vector<camera_frame>> frames;  // by camera, in tick order
    std::vector<task_origin> origins;
    std::map<std::uint32_t, std::int64_t> cancels;
    std::vector<target_sample> samples;
    std::map<std::pair<std::uint32_t, std::string>, std::uint64_t> sent;
    std::map<std::uint32_t, std::map<std::int64_t, std::uint64_t>> sent_by_tick;  // task, tick
    std::map<std::pair<std::uint32_t, std::string>, std::uint64_t> sent_after_cancel;
  };
  contents take();
  /// What a worker hands over while its run goes on (actors::worker_setup::stream_log): the
  /// frames and message counts recorded since the last call, and every pick known. The picks
  /// and cancellations stay: later frames are recorded against them.
  contents take_recorded();
  /// Adds what a worker's cameras recorded (its `take()`): their frames, the picks not known
  /// here yet, and the messages they counted. Samples and cancellations are the coordinator's.
  void add_worker_share(contents part);

 private:
  bool with_visible_ = false;
  mutable std::mutex mutex_;
  contents data_;
};

/// Records where every task's target is in `frame` (published once per tick, phase network).
void sample_targets(observation_log& log, const world::snapshot& frame);

}  // namespace argus::eval
