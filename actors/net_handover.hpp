#pragma once

#include <cstdint>
#include <vector>

#include "actors/ordered_inbox.hpp"
#include "protocol/net_message.hpp"

namespace argus::actors {

/// Network messages a link hands to a node ahead of time, each with the tick it is due: the
/// node reads `messages[i]` in its turn of tick `due[i]`, not before (docs/network.md,
/// "Hand-over on arrival").
///
/// Two parallel runs rather than one of pairs: the node scans the due ticks every turn and
/// reads a message once, when it is due; the ticks of a whole hand-over fit in a cache line.
struct net_handover {
  std::vector<std::int64_t> due;
  std::vector<protocol::net_message> messages;

  void add(std::int64_t due_tick, protocol::net_message message) {
    due.push_back(due_tick);
    messages.push_back(std::move(message));
  }

  void reserve(std::size_t n) {
    due.reserve(n);
    messages.reserve(n);
  }

  std::size_t size() const noexcept { return messages.size(); }
  bool empty() const noexcept { return messages.empty(); }

  friend bool operator==(const net_handover&, const net_handover&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, net_handover& x) {
  return f(x.due, x.messages);
}

/// A hand-over as its node receives it: stamped with the turn of the flush it answers (the
/// link's id as sender, the first message's sequence number), whether the clock announced it,
/// and the end it comes from. One value per CAF message, like `net_send_mail`.
struct net_deliver_mail {
  mail_stamp stamp;
  bool announced = false;
  int from = 0;
  net_handover handover;

  friend bool operator==(const net_deliver_mail&, const net_deliver_mail&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, net_deliver_mail& x) {
  return f(x.stamp, x.announced, x.from, x.handover);
}

}  // namespace argus::actors
