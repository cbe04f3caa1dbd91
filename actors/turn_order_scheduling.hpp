#pragma once

#include <atomic>
#include <cstddef>
#include <mutex>
#include <thread>

#include "caf/logger.hpp"
#include "caf/policy/work_stealing.hpp"
#include "caf/resumable.hpp"

namespace argus::actors {

/// CAF's work-stealing scheduler with one change of order: an actor a worker makes ready goes
/// to the back of that worker's queue, not the front, and thieves take from the front
/// (docs/runtime.md, "Scheduling order").
///
/// Front first (CAF's choice) runs a receiver at once, while the mail is in cache: right for
/// request chains. A simulation turn is a fan-out instead: every node mails each of its links,
/// every link mails the node at its other end. Run at once, every message costs an activation
/// of its own; queued behind the rest of the turn, a link finds both its ends' windows waiting,
/// and a node all its links' hand-overs, and each reads them in one activation. With thousands
/// of actors each activation is a round of cache misses over a 1 KB actor, so fewer is faster.
///
/// Thieves take from the front because CAF's queue takes its back by walking the list from
/// the front under both locks: harmless when the back is the oldest few jobs, a stall when an
/// owner appends tens of thousands.
///
/// Its workers also leave CAF's logger: see `dequeue`.
class turn_order_scheduling : public caf::policy::work_stealing {
 public:
  /// Counts the workers asleep (see `dequeue`), so that a busy worker can hand one a job.
  struct coordinator_data : caf::policy::work_stealing::coordinator_data {
    using caf::policy::work_stealing::coordinator_data::coordinator_data;
    std::atomic<std::size_t> asleep{0};
  };

  /// A job made ready on a worker that has others queued goes to a worker asleep, if there is
  /// one, waking it; otherwise to the back of this worker's queue. One job at a time stays
  /// here: a chain of mail runs on one thread, without a wake-up on the way.
  template <class Worker>
  void internal_enqueue(Worker* self, caf::resumable* job) {
    auto& data = d(self);
    if (!data.queue.empty() && d(self->parent()).asleep.load(std::memory_order_relaxed) > 0)
      if (auto* sleeper = find_asleep(self)) {
        sleeper->external_enqueue(job);
        return;
      }
    data.queue.append(job);
  }

  /// The next job for `self`: its own queue first, then other workers' queues, polling hard,
  /// then gently (`system_config` turns this off), then asleep until a job is enqueued from
  /// outside or handed over (`internal_enqueue`), or a relaxed interval passes (CAF's three
  /// strategies, read from the same configuration).
  ///
  /// Each worker thread first leaves CAF's logger. Debian's CAF is built with the logger in,
  /// and for every job it runs, a worker (and the actor) records the actor's id in the
  /// logger's per-thread table, under a lock that all workers share, even with logging off:
  /// four atomic writes to one cache line, passed from core to core, per activation. Argus
  /// keeps CAF's log quiet (`system_config`), so there is nothing to record.
  template <class Worker>
  caf::resumable* dequeue(Worker* self) {
    static thread_local const bool left_logger = [] {
      caf::logger::set_current_actor_system(nullptr);
      return true;
    }();
    (void)left_logger;
    auto& data = d(self);
    for (std::size_t k = 0; k < 2; ++k) {
      const auto& s = data.strategies[k];
      for (std::size_t i = 0; i < s.attempts; i += s.step_size) {
        if (auto job = data.queue.take_head()) return job;
        if (i % s.steal_interval == 0)
          if (auto job = steal(self)) return job;
        if (s.sleep_duration.count() > 0) std::this_thread::sleep_for(s.sleep_duration);
      }
    }
    const auto& relaxed = data.strategies[2];
    auto& asleep = d(self->parent()).asleep;
    for (std::size_t i = 1;; ++i) {
      bool woken = false;
      {
        std::unique_lock<std::mutex> guard(data.waitdata.lock);
        data.waitdata.sleeping = true;
        asleep.fetch_add(1, std::memory_order_relaxed);
        woken = data.waitdata.cv.wait_for(guard, relaxed.sleep_duration,
                                          [&] { return !data.queue.empty(); });
        asleep.fetch_sub(1, std::memory_order_relaxed);
        data.waitdata.sleeping = false;
      }
      if (woken) {
        if (auto job = data.queue.take_head()) return job;
      } else if (i % relaxed.steal_interval == 0) {
        if (auto job = steal(self)) return job;
      }
    }
  }

 private:
  // Another worker asleep on its queue, if one is: the first after `self` in id order.
  template <class Worker>
  static Worker* find_asleep(Worker* self) {
    auto parent = self->parent();
    const auto n = parent->num_workers();
    for (std::size_t k = 1; k < n; ++k) {
      auto* other = parent->worker_by_id((self->id() + k) % n);
      auto& wait = d(other).waitdata;
      std::lock_guard<std::mutex> guard(wait.lock);
      if (wait.sleeping) return other;
    }
    return nullptr;
  }

  // The oldest job of a random other worker, if it has one.
  template <class Worker>
  caf::resumable* steal(Worker* self) {
    auto parent = self->parent();
    auto n = parent->num_workers();
    if (n < 2) return nullptr;
    auto& data = d(self);
    auto victim = data.uniform(data.rengine);
    if (victim == self->id()) victim = n - 1;
    auto& queue = d(parent->worker_by_id(victim)).queue;
    return queue.empty() ? nullptr : queue.take_head();
  }
};

}  // namespace argus::actors
