#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "actors/net_send_batch.hpp"
#include "actors/type_ids.hpp"

namespace argus::actors {

/// A node's outgoing side of its links. What the node sends on a link in one turn is queued
/// here and handed to the link once per lookahead window, as one CAF message holding every
/// turn's batch with its own stamp (docs/network.md, "Outbox").
///
/// Windows are aligned to the tick grid: a window ends at each tick t with (t + 1) % L == 0,
/// so both ends of a link hand over in the same turn and the link reads both at t + 1. Nothing
/// sent in a window is due before the tick after it ends (L is the minimum delay), so the
/// link still hands everything over in time.
class link_outbox {
 public:
  explicit link_outbox(std::int64_t lookahead) : lookahead_(std::max<std::int64_t>(1, lookahead)) {}

  /// Whether a window ends with `tick`: what is queued must go to the links in this turn.
  bool window_ends(std::int64_t tick) const noexcept { return (tick + 1) % lookahead_ == 0; }

  /// Queues `messages`, sent in the turn `stamp`, for the link with participant id `link_id`.
  void add(std::uint64_t link_id, const caf::actor& link, mail_stamp stamp,
           std::vector<protocol::net_message> messages) {
    auto it = std::find_if(queues_.begin(), queues_.end(),
                           [&](const queue& q) { return q.link_id == link_id; });
    if (it == queues_.end()) it = queues_.insert(queues_.end(), queue{link_id, link, {}});
    it->batches.push_back(net_send_batch{stamp, std::move(messages)});
  }

  /// Hands each link what is queued for it, as `(net_send_atom, int from, batches)`, and calls
  /// `on_handed(link_id)` for each, so the caller can have the clock wake that link.
  template <class Self, class OnHanded>
  void flush(Self* self, int from, OnHanded on_handed) {
    for (auto& q : queues_) {
      if (q.batches.empty()) continue;
      self->send(q.link, net_send_atom_v, from, std::move(q.batches));
      q.batches.clear();
      on_handed(q.link_id);
    }
  }

  /// Whether nothing is queued.
  bool empty() const noexcept {
    return std::all_of(queues_.begin(), queues_.end(),
                       [](const queue& q) { return q.batches.empty(); });
  }

 private:
  struct queue {
    std::uint64_t link_id = 0;
    caf::actor link;
    std::vector<net_send_batch> batches;
  };
  std::int64_t lookahead_;
  std::vector<queue> queues_;
};

}  // namespace argus::actors
