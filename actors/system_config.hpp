#pragma once

#include "actors/scheduling_order.hpp"
#include "actors/turn_order_scheduling.hpp"
#include "actors/type_ids.hpp"
#include "caf/scheduler/coordinator.hpp"
#include "caf/scheduler/test_coordinator.hpp"

namespace argus::actors {

/// The CAF configuration every Argus actor system uses: our message types registered,
/// `threads` scheduler workers in `order`, and CAF's own log files off.
class system_config : public caf::actor_system_config {
 public:
  explicit system_config(unsigned threads, scheduling_order order = scheduling_order::turn_order) {
    add_message_types<caf::id_block::argus>();
    set("scheduler.max-threads", static_cast<size_t>(threads));
    set("logger.file-verbosity", caf::atom("quiet"));
    set("logger.console-verbosity", caf::atom("quiet"));
    if (order == scheduling_order::turn_order) {
      // An idle worker polls hard a hundred times, then sleeps until it is handed a job
      // (turn_order_scheduling::internal_enqueue). CAF's default naps 50 us at a time for 25 ms
      // first: in a lockstep run every worker idles at each barrier, so the naps woke each
      // thread 20,000 times a second, and the processes of a distributed run on one machine
      // spent a third of their time switching in and out of them (docs/runtime.md).
      set("work-stealing.moderate-poll-attempts", size_t{0});
      module_factories.push_back([](caf::actor_system& sys) -> caf::actor_system::module* {
        // CAF's deterministic test coordinator, where a test fixture asks for it.
        auto policy = caf::get_or(sys.config(), "scheduler.policy", caf::atom("stealing"));
        if (policy == caf::atom("testing")) return new caf::scheduler::test_coordinator(sys);
        return new caf::scheduler::coordinator<turn_order_scheduling>(sys);
      });
    }
  }
};

}  // namespace argus::actors
