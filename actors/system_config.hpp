#pragma once

#include "actors/type_ids.hpp"

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
  }
};

}  // namespace argus::actors
