#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

#include "config/scenario.hpp"
#include "eval/observation_log.hpp"
#include "eval/oracle_assignment.hpp"
#include "protocol/group_messages.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::eval {

/// The central oracle of `controller.strategy: oracle`, where every camera node reads its orders.
/// The assignment of a tick is made once, by the first node to ask in phase cameras, from
/// inputs that are complete before that phase: the tick's snapshot, the tasks known before the
/// tick, and the cameras that recorded a frame in the tick before (alive). So it is the same
/// whichever node asks first, on any thread.
class oracle_board {
 public:
  oracle_board(const config::scenario& scenario, std::shared_ptr<const world::station> station,
               std::shared_ptr<observation_log> log)
      : scenario_(scenario), station_(std::move(station)), log_(std::move(log)) {}

  /// The task camera `camera` is to perform in the frame of `snapshot`, if any.
  std::optional<std::uint32_t> task_of(int camera, const world::snapshot& frame) {
    std::lock_guard<std::mutex> guard(mutex_);
    const auto tick = static_cast<std::int64_t>(frame.tick());
    if (tick != tick_) {
      previous_ = std::move(current_);
      current_ = assign_cameras(scenario_.cameras, log_->cameras_alive(tick - 1), frame, *station_,
                                targets(tick), previous_);
      tick_ = tick;
    }
    auto it = current_.find(camera);
    if (it == current_.end()) return std::nullopt;
    return it->second;
  }

  /// controller.oracle_signature: operator: the tasked camera leaves the signature of the
  /// operator's pick here, in the turn it records the task's origin; the oracle assigns a task
  /// only from the tick after its origin, so every camera finds it there, on any thread.
  void put_signature(std::uint32_t task, protocol::signature signature) {
    std::lock_guard<std::mutex> guard(mutex_);
    signatures_.insert_or_assign(task, std::move(signature));
  }
  std::optional<protocol::signature> signature(std::uint32_t task) const {
    std::lock_guard<std::mutex> guard(mutex_);
    auto it = signatures_.find(task);
    if (it == signatures_.end()) return std::nullopt;
    return it->second;
  }

 private:
  std::vector<oracle_target> targets(std::int64_t tick) const {
    std::vector<oracle_target> out;
    for (const auto& o : log_->origins()) {
      if (o.tick >= tick || o.task >= scenario_.tasks.size()) continue;
      out.push_back({o.task, o.pedestrian, scenario_.tasks[o.task].cameras_max()});
    }
    return out;
  }

  config::scenario scenario_;
  std::shared_ptr<const world::station> station_;
  std::shared_ptr<observation_log> log_;
  mutable std::mutex mutex_;
  std::int64_t tick_ = -1;
  std::map<int, std::uint32_t> current_;
  std::map<int, std::uint32_t> previous_;
  std::map<std::uint32_t, protocol::signature> signatures_;
};

}  // namespace argus::eval
