#pragma once

#include <cstdint>
#include <vector>

#include "actors/ordered_inbox.hpp"
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

/// A window as its link receives it: the sending end, the turn it was flushed in, and whether
/// the clock was told (the link then answers with a hand-over even when it is empty).
///
/// One value per CAF message, no atom: CAF stores a type tag beside every value of a message
/// and checks them one by one, and at ten thousand nodes each is read from a cold cache line.
struct net_send_mail {
  int from = 0;
  mail_stamp flushed;
  bool announced = false;
  net_send_window window;

  friend bool operator==(const net_send_mail&, const net_send_mail&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, net_send_mail& x) {
  return f(x.from, x.flushed, x.announced, x.window);
}

}  // namespace argus::actors
