#pragma once

#include <cstddef>
#include <functional>

#include "distributed/endpoint.hpp"
#include "distributed/tls_files.hpp"

namespace argus::distributed {

/// What `argus worker` serves with.
struct worker_options {
  endpoint listen{"127.0.0.1", 7001};
  /// Scheduler threads; 0 = one per hardware thread.
  unsigned threads = 0;
  /// Renderers for pixel sensing; 0 = as many as scheduler threads.
  std::size_t render_threads = 0;
  /// Its TLS identity; required to listen beyond loopback.
  tls_files tls;
};

/// Publishes a worker host (actors/worker_host.hpp) at `options.listen` and serves runs, one at a
/// time, until `stop()` returns true (polled every 100 ms). Calls `listening(port)` once the
/// port is bound. With `options.tls` every connection is TLS with mutual authentication.
/// Throws std::invalid_argument when asked to listen beyond loopback without TLS, or for wrong
/// TLS files (check_tls_files); std::runtime_error when it cannot listen.
void serve_worker(const worker_options& options, const std::function<void(unsigned)>& listening,
                  const std::function<bool()>& stop);

}  // namespace argus::distributed
