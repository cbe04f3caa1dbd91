#pragma once

// The one rule for "this machine only", for the workers, the coordinator and the live console
// alike: beyond it, each requires authentication (docs/distributed.md, docs/serve.md).

#include <string_view>

namespace argus::distributed {

/// Whether `host` names this machine's loopback only (localhost, 127.x.y.z, ::1).
inline bool is_loopback_host(std::string_view host) {
  return host == "localhost" || host == "::1" || host.starts_with("127.");
}

}  // namespace argus::distributed
