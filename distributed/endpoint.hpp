#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace argus::distributed {

/// Where a worker listens or a coordinator connects: HOST:PORT.
struct endpoint {
  std::string host;
  std::uint16_t port = 0;

  std::string to_string() const { return host + ":" + std::to_string(port); }
  /// Whether `host` names this machine's loopback only (localhost, 127.x.y.z, ::1).
  bool loopback() const;
};

/// Reads `text` as HOST:PORT (an IPv6 host in brackets: [::1]:7001); port 0 (the system
/// chooses) only where `any_port`. Throws std::invalid_argument saying what `what` (the
/// option) expected.
endpoint parse_endpoint(std::string_view text, std::string_view what, bool any_port = false);

/// Reads a comma-separated list of HOST:PORT (`--workers`).
std::vector<endpoint> parse_endpoints(std::string_view text, std::string_view what);

}  // namespace argus::distributed
