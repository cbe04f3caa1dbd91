// The scheduling order every Argus actor system runs in (actors/turn_order_scheduling.hpp):
// an actor made ready in a turn runs after what was ready before it, so mail sent to it from
// several places in one fan-out is read in one go. Real workers, not the test coordinator:
// the order is the scheduler's.

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "actors/system_config.hpp"

namespace argus::actors {
namespace {

struct trace {
  std::mutex lock;
  std::vector<std::string> lines;

  void add(std::string line) {
    std::lock_guard<std::mutex> guard(lock);
    lines.push_back(std::move(line));
  }
};

// Logs each message it reads and, with it, how many messages that activation found waiting.
caf::behavior receiver(caf::event_based_actor* self, std::string name, std::shared_ptr<trace> log) {
  return {
      [=](int i) {
        auto waiting = self->mailbox().size();
        log->add(name + ":" + std::to_string(i) + " +" + std::to_string(waiting));
        if (i == 2 || name == "c") self->quit();
      },
  };
}

// Fans out as a node's turn does: b, then c, then b again.
caf::behavior fan_out(caf::event_based_actor* self, caf::actor b, caf::actor c) {
  return {
      [=](caf::atom_value) {
        self->send(b, 1);
        self->send(c, 1);
        self->send(b, 2);
        self->quit();
      },
  };
}

std::vector<std::string> run(scheduling_order order) {
  system_config cfg(1, order);
  auto log = std::make_shared<trace>();
  {
    caf::actor_system sys{cfg};
    auto b = sys.spawn(receiver, "b", log);
    auto c = sys.spawn(receiver, "c", log);
    caf::anon_send(sys.spawn(fan_out, b, c), caf::atom("go"));
    b = c = caf::actor{};
    sys.await_all_actors_done();
  }
  return log->lines;
}

TEST(turn_order_scheduling,
     a_receiver_runs_after_the_rest_of_the_fan_out_and_reads_its_mail_at_once) {
  // b was made ready first, so it runs first, after the fan-out is over: both its messages
  // are waiting, and it reads them in one activation, before c.
  EXPECT_EQ(run(scheduling_order::turn_order),
            (std::vector<std::string>{"b:1 +1", "b:2 +0", "c:1 +0"}));
}

TEST(turn_order_scheduling, cafs_order_runs_the_last_made_ready_first) {
  // The baseline the benchmarks compare against: c, made ready last, runs first.
  EXPECT_EQ(run(scheduling_order::caf_default),
            (std::vector<std::string>{"c:1 +0", "b:1 +1", "b:2 +0"}));
}

// The second of two jobs made ready: records its thread and tells the first it has run.
struct rendezvous {
  std::mutex lock;
  std::condition_variable done;
  bool second_ran = false;
  std::thread::id second_thread;
};

// The first job: holds its worker until the second has run elsewhere, or 2 s have passed.
caf::behavior holds_its_worker(caf::event_based_actor* self, std::shared_ptr<rendezvous> r) {
  return {
      [=](int) {
        std::unique_lock<std::mutex> guard(r->lock);
        r->done.wait_for(guard, std::chrono::seconds(2), [&] { return r->second_ran; });
        self->quit();
      },
  };
}

caf::behavior records_its_thread(caf::event_based_actor* self, std::shared_ptr<rendezvous> r) {
  return {
      [=](int) {
        {
          std::lock_guard<std::mutex> guard(r->lock);
          r->second_ran = true;
          r->second_thread = std::this_thread::get_id();
        }
        r->done.notify_all();
        self->quit();
      },
  };
}

// Makes b ready, then c, as a node's turn makes its links ready; records its own thread.
caf::behavior fan_out_from(caf::event_based_actor* self, caf::actor b, caf::actor c,
                           std::shared_ptr<std::thread::id> ran_on) {
  return {
      [=](caf::atom_value) {
        *ran_on = std::this_thread::get_id();
        self->send(b, 1);
        self->send(c, 1);
        self->quit();
      },
  };
}

TEST(turn_order_scheduling, a_worker_with_work_queued_hands_the_next_job_to_a_sleeping_worker) {
  // Both workers are asleep when a fan-out makes b, then c, ready. b stays in the fan-out's
  // worker's queue and, once run, holds that worker until c has run. c must be handed to the
  // other worker, which wakes for it: left queued behind b it would run only after b gave up,
  // on b's thread, since here a sleeping worker does not look for work on its own in time.
  system_config cfg(2);
  cfg.set("work-stealing.relaxed-sleep-duration", caf::timespan{std::chrono::seconds(10)});
  caf::actor_system sys{cfg};
  for (int k = 0; k < 3; ++k) {
    auto fan = std::make_shared<std::thread::id>();
    auto r = std::make_shared<rendezvous>();
    auto b = sys.spawn(holds_its_worker, r);
    auto c = sys.spawn(records_its_thread, r);
    auto fan_out = sys.spawn(fan_out_from, b, c, fan);
    b = c = caf::actor{};
    // Spawning woke the workers (each new actor starts on one); let them fall asleep again.
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    caf::anon_send(fan_out, caf::atom("go"));
    fan_out = caf::actor{};
    sys.await_all_actors_done();
    EXPECT_NE(r->second_thread, *fan) << "try " << k;
  }
}

}  // namespace
}  // namespace argus::actors
