#pragma once

#include <vector>

#include "actors/remote_network.hpp"
#include "caf/fwd.hpp"

namespace argus::actors {

/// The workers a distributed run places its cameras and links on (docs/distributed.md). The
/// network layer lives behind this: `argus run --workers` gives a pool that connects over
/// CAF's middleman (distributed/), tests one that spawns worker hosts in the run's own process.
class worker_pool {
 public:
  virtual ~worker_pool() = default;
  /// Loads what connecting needs into the run's configuration, before its actor system exists.
  virtual void configure(caf::actor_system_config& cfg) const = 0;
  /// Reaches every worker; throws std::runtime_error naming the first it cannot reach.
  virtual std::vector<worker_contact> connect(caf::actor_system& system) const = 0;
};

}  // namespace argus::actors
