#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <tuple>
#include <vector>

#include "actors/net_delivery.hpp"
#include "actors/ordered_inbox.hpp"
#include "actors/phase.hpp"
#include "caf/actor.hpp"

namespace argus::actors {

/// A node's side of its links: what they handed over ahead of time, held until each message
/// is due, read in canonical order, and taken back when a link says the message never
/// arrived (a cut caught it on the wire). Links are not ticked by the clock, so it also holds
/// the node's turn until every hand-over announced for it has come (docs/network.md,
/// "Announced hand-overs").
class net_arrivals {
 public:
  struct arrival {
    int from = 0;
    protocol::net_message message;
  };

  /// A turn the clock gave: answer `clock` once it is taken.
  struct turn {
    std::int64_t tick = 0;
    std::uint8_t phase = 0;
    caf::actor clock;
  };

  /// Stores a hand-over `(net_deliver_atom, stamp, announced, from, batch)`: the i-th message
  /// is stamped (its due tick, network phase, the link, stamp.seq + i). An announced one
  /// answers what its sender flushed in the turn (stamp.tick, stamp.phase).
  void put(const mail_stamp& stamp, bool announced, int from, std::vector<net_delivery>& batch) {
    if (announced) announced_.emplace_back(stamp.tick, stamp.phase);
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

  /// Holds turn `t` until the `relayed` hand-overs announced for it (flushed before it) are in.
  void hold(turn t, std::uint32_t relayed) {
    held_ = std::move(t);
    relayed_ = relayed;
  }

  /// The held turn once everything it waits for has come, else nothing.
  std::optional<turn> take_ready() {
    if (!held_) return std::nullopt;
    auto before = [&](const auto& s) { return s < std::make_tuple(held_->tick, held_->phase); };
    auto have =
        static_cast<std::size_t>(std::count_if(announced_.begin(), announced_.end(), before));
    if (have < relayed_) return std::nullopt;
    std::erase_if(announced_, before);
    auto t = std::move(held_);
    held_.reset();
    return t;
  }

  /// Everything due before (`tick`, `phase`), in canonical order.
  std::vector<std::pair<mail_stamp, arrival>> take_due(std::int64_t tick, std::uint8_t phase) {
    return inbox_.take_due(tick, phase);
  }

  /// Number of messages held.
  std::size_t size() const noexcept { return inbox_.size(); }

 private:
  ordered_inbox<arrival> inbox_;
  std::vector<std::tuple<std::int64_t, std::uint8_t>> announced_;  // not yet counted
  std::optional<turn> held_;
  std::uint32_t relayed_ = 0;
};

}  // namespace argus::actors
