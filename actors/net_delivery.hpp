#pragma once

#include <cstdint>

#include "protocol/net_message.hpp"

namespace argus::actors {

/// One network message a link hands to a node ahead of time: the node reads it in its turn of
/// tick `due`, not before (docs/network.md, "Hand-over on arrival").
struct net_delivery {
  std::int64_t due = 0;
  protocol::net_message message;

  friend bool operator==(const net_delivery&, const net_delivery&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, net_delivery& x) {
  return f(x.due, x.message);
}

}  // namespace argus::actors
