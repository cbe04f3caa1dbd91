#pragma once

#include <cstdint>
#include <vector>

#include "actors/ordered_inbox.hpp"
#include "protocol/net_message.hpp"

namespace argus::actors {

/// What one endpoint sent on one link in one lookahead window (docs/network.md, "Outbox"):
/// every turn's messages in one flat run, and where each turn's share ends. A link reads the
/// turns in the canonical order of their stamps, however late the window reached it.
///
/// Flat because a window is the unit the link layer moves: one allocation per link per
/// window, however many turns and messages it holds, and the link reads it front to back.
struct net_send_window {
  /// messages[previous turn's end, end) were sent in the turn `stamp`.
  struct turn {
    mail_stamp stamp;
    std::uint32_t end = 0;

    friend bool operator==(const turn&, const turn&) = default;
  };

  std::vector<turn> turns;
  std::vector<protocol::net_message> messages;

  /// Appends `message`, sent in the turn `stamp` (turns are added in the order they happen).
  void add(const mail_stamp& stamp, protocol::net_message message) {
    if (turns.empty() || turns.back().stamp != stamp) turns.push_back(turn{stamp, 0});
    messages.push_back(std::move(message));
    turns.back().end = static_cast<std::uint32_t>(messages.size());
  }

  bool empty() const noexcept { return messages.empty(); }

  friend bool operator==(const net_send_window&, const net_send_window&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, net_send_window::turn& x) {
  return f(x.stamp, x.end);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, net_send_window& x) {
  return f(x.turns, x.messages);
}

}  // namespace argus::actors
