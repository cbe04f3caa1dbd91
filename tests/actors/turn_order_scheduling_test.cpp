// The scheduling order every Argus actor system runs in (actors/turn_order_scheduling.hpp):
// an actor made ready in a turn runs after what was ready before it, so mail sent to it from
// several places in one fan-out is read in one go. Real workers, not the test coordinator:
// the order is the scheduler's.

#include <gtest/gtest.h>

#include <memory>
#include <mutex>
#include <string>
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

}  // namespace
}  // namespace argus::actors
