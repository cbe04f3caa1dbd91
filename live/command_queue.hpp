#pragma once

#include <cstddef>
#include <deque>
#include <mutex>
#include <vector>

#include "live/command.hpp"

namespace argus::live {

/// Commands the operator sent and the run has not yet taken: the server pushes from its
/// threads; the scenario script (tasks) and the fault injector (faults) take theirs at the
/// start of their turn, which fixes the tick at which each takes effect. Bounded, so that a
/// flood of requests cannot grow it without end.
class command_queue {
 public:
  /// At most this many commands wait at once.
  static constexpr std::size_t capacity = 256;

  /// Queues `c`; false (and nothing queued) when `capacity` commands already wait.
  bool push(const command& c) {
    std::lock_guard<std::mutex> guard(mutex_);
    if (waiting_.size() >= capacity) return false;
    waiting_.push_back(c);
    return true;
  }

  /// Takes every waiting task command (`tasks` true: task, cancel) or fault command (`tasks`
  /// false), in the order they were sent; the others stay.
  std::vector<command> take(bool tasks) {
    std::vector<command> out;
    std::lock_guard<std::mutex> guard(mutex_);
    for (auto it = waiting_.begin(); it != waiting_.end();) {
      if (is_task_command(it->kind) == tasks) {
        out.push_back(*it);
        it = waiting_.erase(it);
      } else {
        ++it;
      }
    }
    return out;
  }

 private:
  std::mutex mutex_;
  std::deque<command> waiting_;
};

}  // namespace argus::live
