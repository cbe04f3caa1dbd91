#pragma once

#include <cstdint>
#include <vector>

#include "actors/net_delivery.hpp"
#include "actors/ordered_inbox.hpp"
#include "actors/phase.hpp"

namespace argus::actors {

/// A node's side of its links: what they handed over ahead of time, held until each message
/// is due, read in canonical order, and taken back when a link says the message never
/// arrived (a cut caught it on the wire).
class net_arrivals {
 public:
  struct arrival {
    int from = 0;
    protocol::net_message message;
  };

  /// Stores a hand-over `(net_deliver_atom, stamp, from, batch)`: the i-th message is stamped
  /// (its due tick, network phase, the link, stamp.seq + i).
  void put(const mail_stamp& stamp, int from, std::vector<net_delivery>& batch) {
    auto seq = stamp.seq;
    for (auto& d : batch)
      inbox_.put(mail_stamp{d.due, static_cast<std::uint8_t>(phase::network), stamp.sender, seq++},
                 arrival{from, std::move(d.message)});
  }

  /// Takes back everything link `link_id` handed over that is due at `from_due` or later.
  void retract(std::uint64_t link_id, std::int64_t from_due) {
    inbox_.discard_if(
        [&](const mail_stamp& s) { return s.sender == link_id && s.tick >= from_due; });
  }

  /// Everything due before (`tick`, `phase`), in canonical order.
  std::vector<std::pair<mail_stamp, arrival>> take_due(std::int64_t tick, std::uint8_t phase) {
    return inbox_.take_due(tick, phase);
  }

  /// Number of messages held.
  std::size_t size() const noexcept { return inbox_.size(); }

 private:
  ordered_inbox<arrival> inbox_;
};

}  // namespace argus::actors
