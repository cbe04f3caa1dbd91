#pragma once

#include <chrono>
#include <vector>

#include "actors/worker_pool.hpp"
#include "distributed/endpoint.hpp"
#include "distributed/tls_files.hpp"

namespace argus::distributed {

/// How long a coordinator tries to reach a worker before it reports it by name.
inline constexpr std::chrono::seconds connect_timeout{10};

/// The workers of `argus run --workers`, reached over CAF's middleman (with `tls` given, over
/// `caf_openssl`): the worker host each `argus worker` published (actors/worker_host.hpp).
class network_workers final : public actors::worker_pool {
 public:
  /// Throws std::invalid_argument when a worker beyond loopback is named without TLS, or when
  /// the TLS files are wrong (check_tls_files).
  network_workers(std::vector<endpoint> workers, tls_files tls);
  void configure(caf::actor_system_config& cfg) const override;
  std::vector<actors::worker_contact> connect(caf::actor_system& system) const override;

 private:
  std::vector<endpoint> workers_;
  tls_files tls_;
};

}  // namespace argus::distributed
