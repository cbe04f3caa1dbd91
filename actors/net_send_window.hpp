#pragma once

#include <cstdint>
#include <vector>

#include "protocol/net_message.hpp"

namespace argus::actors {

/// What one endpoint sent on one link in one lookahead window (docs/network.md, "Outbox"):
/// every turn's messages in one flat run, and where the share of each tick it sent in ends.
/// The link judges a message by its send tick (a cut or a loss burst applies by when a message
/// was sent), and needs nothing else of the turn it was sent in.
///
/// Flat because a window is the unit the link layer moves: one allocation per link per
/// window, however many turns and messages it holds, and the link reads it front to back. A
/// tick's mark is 16 bytes: a window of Table 2's three ticks marks them in one cache line.
struct net_send_window {
  /// messages[previous tick's end, end) were sent at `tick`.
  struct sent_at {
    std::int64_t tick = 0;
    std::uint32_t end = 0;

    friend bool operator==(const sent_at&, const sent_at&) = default;
  };

  std::vector<sent_at> ticks;
  std::vector<protocol::net_message> messages;

  /// Appends `message`, sent at `tick` (ticks are added in the order they happen).
  void add(std::int64_t tick, protocol::net_message message) {
    if (ticks.empty() || ticks.back().tick != tick) ticks.push_back(sent_at{tick, 0});
    messages.push_back(std::move(message));
    ticks.back().end = static_cast<std::uint32_t>(messages.size());
  }

  bool empty() const noexcept { return messages.empty(); }

  friend bool operator==(const net_send_window&, const net_send_window&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, net_send_window::sent_at& x) {
  return f(x.tick, x.end);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, net_send_window& x) {
  return f(x.ticks, x.messages);
}

}  // namespace argus::actors
