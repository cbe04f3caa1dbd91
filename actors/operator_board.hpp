#pragma once

#include <cstdint>
#include <mutex>
#include <vector>

#include "config/scenario.hpp"

namespace argus::actors {

/// A live operator order for one camera: a task issued through it, or a task's cancellation.
struct operator_order {
  std::int64_t tick = 0;
  int camera = 0;
  std::uint32_t task = 0;
  bool cancel = false;
  /// The task itself (not for a cancellation).
  config::operator_task request;
};

/// The operator's live orders (argus serve), where camera nodes find those for them: what a
/// node of a replayed run has from the scenario's `tasks` when it starts, a live node reads
/// here in its turn. The scenario script publishes in phase faults and nodes read in phase
/// cameras of the same tick; the clock's phase barrier orders every read after that tick's
/// publications and before the next, so what a node reads depends on the tick alone. A board,
/// not mail, for the reason of snapshot_board: a camera that recovers is a new actor, and it
/// finds every order here, as a replayed one finds them in the scenario.
class operator_board {
 public:
  /// Publishes `order` (phase faults).
  void publish(operator_order order) {
    std::lock_guard<std::mutex> guard(mutex_);
    orders_.push_back(std::move(order));
  }

  /// The orders for `camera` published since `cursor` (phase cameras); moves `cursor` past them.
  std::vector<operator_order> take_new(std::size_t& cursor, int camera) const {
    std::vector<operator_order> out;
    std::lock_guard<std::mutex> guard(mutex_);
    for (; cursor < orders_.size(); ++cursor)
      if (orders_[cursor].camera == camera) out.push_back(orders_[cursor]);
    return out;
  }

  /// Every order published since `cursor`; moves `cursor` past them (the world coordinator of a
  /// live run across workers, phase network, passes them on to the workers).
  std::vector<operator_order> take_all_new(std::size_t& cursor) const {
    std::lock_guard<std::mutex> guard(mutex_);
    std::vector<operator_order> out(orders_.begin() + static_cast<std::ptrdiff_t>(cursor),
                                    orders_.end());
    cursor = orders_.size();
    return out;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<operator_order> orders_;
};

}  // namespace argus::actors
