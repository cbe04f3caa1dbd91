#pragma once

#include <cstdlib>

#include "actors/turn_order_scheduling.hpp"
#include "actors/type_ids.hpp"
#include "caf/scheduler/coordinator.hpp"

namespace argus::actors {

/// The CAF configuration every Argus actor system uses: our message types registered,
/// `threads` scheduler workers, and CAF's own log files off.
class system_config : public caf::actor_system_config {
 public:
  explicit system_config(unsigned threads) {
    add_message_types<caf::id_block::argus>();
    set("scheduler.max-threads", static_cast<size_t>(threads));
    set("logger.file-verbosity", caf::atom("quiet"));
    set("logger.console-verbosity", caf::atom("quiet"));
    if (std::getenv("ARGUS_FIFO"))
      module_factories.push_back([](caf::actor_system& sys) -> caf::actor_system::module* {
        return new caf::scheduler::coordinator<turn_order_scheduling>(sys);
      });
  }
};

}  // namespace argus::actors
