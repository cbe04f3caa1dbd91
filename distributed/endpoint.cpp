#include "distributed/endpoint.hpp"

#include <charconv>
#include <stdexcept>

#include "distributed/loopback.hpp"
#include "fmt/format.h"

namespace argus::distributed {

bool endpoint::loopback() const {
  return is_loopback_host(host);
}

endpoint parse_endpoint(std::string_view text, std::string_view what, bool any_port) {
  auto bad = [&](std::string_view why) {
    return std::invalid_argument(
        fmt::format("{}: '{}' is not HOST:PORT ({}), e.g. 127.0.0.1:7001", what, text, why));
  };
  const auto colon = text.rfind(':');
  if (colon == std::string_view::npos || colon == 0) throw bad("no host or no port");
  auto host = text.substr(0, colon);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']')
    host = host.substr(1, host.size() - 2);
  else if (host.find(':') != std::string_view::npos)
    throw bad("an IPv6 host goes in brackets");
  const auto port_text = text.substr(colon + 1);
  unsigned port = 0;
  auto [end, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (ec != std::errc{} || end != port_text.data() + port_text.size() || (port == 0 && !any_port) ||
      port > 65535)
    throw bad(any_port ? "the port must be 0 (any) to 65535" : "the port must be 1 to 65535");
  return {std::string(host), static_cast<std::uint16_t>(port)};
}

std::vector<endpoint> parse_endpoints(std::string_view text, std::string_view what) {
  std::vector<endpoint> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    auto comma = text.find(',', start);
    auto item = text.substr(start, comma == std::string_view::npos ? text.npos : comma - start);
    out.push_back(parse_endpoint(item, what));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (out[i].to_string() == out[j].to_string())
        throw std::invalid_argument(
            fmt::format("{}: worker {} is named twice", what, out[i].to_string()));
  return out;
}

}  // namespace argus::distributed
