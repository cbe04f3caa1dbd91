#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "actors/net_handover.hpp"
#include "actors/ordered_inbox.hpp"
#include "actors/phase.hpp"
#include "caf/actor.hpp"

namespace argus::actors {

/// A node's side of its links: what they handed over ahead of time, held until each message
/// is due, read in canonical order, and taken back when a link says the message never
/// arrived (a cut caught it on the wire). Links are not ticked by the clock, so it also holds
/// the node's turn until every hand-over announced for it has come (docs/network.md,
/// "Announced hand-overs").
///
/// Hand-overs are kept as they came, not copied message by message into one queue: a node
/// with eight links holds a few dozen messages, and at ten thousand nodes every copy is a
/// cache miss (bench/RESULTS.md, "Link layer"). A turn scans the due ticks, sorts the few that
/// are due by stamp, and reads each message in place.
class net_arrivals {
 public:
  /// A turn the clock gave: answer `clock` once it is taken.
  struct turn {
    std::int64_t tick = 0;
    std::uint8_t phase = 0;
    caf::actor clock;
  };

  /// Stores a hand-over, taking its storage (`put(stamp, announced, from, handover)` below).
  void put(net_deliver_mail& mail) { put(mail.stamp, mail.announced, mail.from, mail.handover); }

  /// Stores a hand-over `handover` from the link at node `from`, taking its
  /// storage: the i-th message is stamped (its due tick, network phase, the link,
  /// stamp.seq + i). An announced one answers what its sender flushed in the turn
  /// (stamp.tick, stamp.phase).
  void put(const mail_stamp& stamp, bool announced, int from, net_handover& handover) {
    if (announced) announced_.emplace_back(stamp.tick, stamp.phase);
    if (handover.empty()) return;
    earliest_.push_back(*std::min_element(handover.due.begin(), handover.due.end()));
    held_.push_back(held{stamp.sender, stamp.seq, from, std::move(handover)});
  }

  /// Takes back everything link `link_id` handed over that is due at `from_due` or later.
  void retract(std::uint64_t link_id, std::int64_t from_due) {
    for (std::size_t i = 0; i < held_.size(); ++i) {
      auto& h = held_[i];
      if (h.link != link_id) continue;
      for (auto& due : h.handover.due)
        if (due >= from_due) due = gone;
      earliest_[i] = earliest_of(h);
    }
    drop_read();
  }

  /// Holds turn `t` until the `relayed` hand-overs announced for it (flushed before it) are in.
  void hold(turn t, std::uint32_t relayed) {
    held_turn_ = std::move(t);
    relayed_ = relayed;
  }

  /// The held turn once everything it waits for has come, else nothing.
  std::optional<turn> take_ready() {
    if (!held_turn_) return std::nullopt;
    auto before = [&](const auto& s) {
      return s < std::make_tuple(held_turn_->tick, held_turn_->phase);
    };
    auto have =
        static_cast<std::size_t>(std::count_if(announced_.begin(), announced_.end(), before));
    if (have < relayed_) return std::nullopt;
    std::erase_if(announced_, before);
    auto t = std::move(held_turn_);
    held_turn_.reset();
    return t;
  }

  /// Calls `f(const mail_stamp&, int from, protocol::net_message&)` for everything due before
  /// (`tick`, `phase`), in canonical order; each message is read once, then forgotten.
  template <class F>
  void for_each_due(std::int64_t tick, std::uint8_t phase, F f) {
    // A message is stamped in the network phase of its due tick.
    auto last_due = static_cast<std::uint8_t>(phase::network) < phase ? tick : tick - 1;
    due_.clear();
    // Only hand-overs with something due are opened: the rest wait, unread, for later turns.
    for (std::uint32_t h = 0; h < held_.size(); ++h) {
      if (earliest_[h] > last_due) continue;
      const auto& dues = held_[h].handover.due;
      for (std::uint32_t i = 0; i < dues.size(); ++i)
        if (dues[i] <= last_due)
          due_.push_back(due_ref{dues[i], held_[h].link, held_[h].seq + i, h, i});
    }
    if (due_.empty()) return;
    std::sort(due_.begin(), due_.end(), [](const due_ref& a, const due_ref& b) {
      return std::tie(a.due, a.link, a.seq) < std::tie(b.due, b.link, b.seq);
    });
    for (const auto& d : due_) {
      auto& h = held_[d.held];
      f(mail_stamp{d.due, static_cast<std::uint8_t>(phase::network), d.link, d.seq}, h.from,
        h.handover.messages[d.index]);
      h.handover.due[d.index] = gone;
    }
    for (std::uint32_t h = 0; h < held_.size(); ++h)
      if (earliest_[h] <= last_due) earliest_[h] = earliest_of(held_[h]);
    drop_read();
  }

  /// Number of messages held.
  std::size_t size() const noexcept {
    std::size_t n = 0;
    for (const auto& h : held_)
      n += static_cast<std::size_t>(std::count_if(h.handover.due.begin(), h.handover.due.end(),
                                                  [](std::int64_t d) { return d != gone; }));
    return n;
  }

 private:
  // Read or retracted; never due, since no tick reaches it.
  static constexpr std::int64_t gone = std::numeric_limits<std::int64_t>::max();

  struct held {
    std::uint64_t link = 0;
    std::uint64_t seq = 0;  // of the first message
    int from = 0;
    net_handover handover;  // a message read or retracted has its due tick set to `gone`
  };

  struct due_ref {
    std::int64_t due;
    std::uint64_t link;
    std::uint64_t seq;
    std::uint32_t held;
    std::uint32_t index;
  };

  static std::int64_t earliest_of(const held& h) {
    return *std::min_element(h.handover.due.begin(), h.handover.due.end());
  }

  // Hand-overs with nothing left to read go; the order of the rest does not matter (a turn
  // sorts what is due by stamp), so the last takes a leaver's place.
  void drop_read() {
    for (std::size_t i = 0; i < held_.size();) {
      if (earliest_[i] != gone) {
        ++i;
        continue;
      }
      if (i + 1 != held_.size()) {
        held_[i] = std::move(held_.back());
        earliest_[i] = earliest_.back();
      }
      held_.pop_back();
      earliest_.pop_back();
    }
  }

  std::vector<held> held_;
  // The earliest due tick still unread in each hand-over (`gone` when none), beside it: a
  // turn reads this, not the hand-overs, to find what is due.
  std::vector<std::int64_t> earliest_;
  std::vector<due_ref> due_;                                       // scratch, kept for its capacity
  std::vector<std::tuple<std::int64_t, std::uint8_t>> announced_;  // not yet counted
  std::optional<turn> held_turn_;
  std::uint32_t relayed_ = 0;
};

}  // namespace argus::actors
