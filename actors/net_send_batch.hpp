#pragma once

#include <vector>

#include "actors/ordered_inbox.hpp"
#include "protocol/net_message.hpp"

namespace argus::actors {

/// What one endpoint sent on one link in one turn, stamped with that turn: a link reads each
/// batch in the canonical order of its stamp, however late it arrived (docs/network.md,
/// "Outbox").
struct net_send_batch {
  mail_stamp stamp;
  std::vector<protocol::net_message> messages;

  friend bool operator==(const net_send_batch&, const net_send_batch&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, net_send_batch& x) {
  return f(x.stamp, x.messages);
}

}  // namespace argus::actors
