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
/// Windows are aligned to the tick grid: a window ends at each tick t with (t + 1) % L == 0.
/// Nothing sent in a window is due before the tick after it ends (L is the minimum delay), so
/// a link that hands everything over as soon as it reads it is always in time.
class link_outbox {
 public:
  explicit link_outbox(std::int64_t lookahead) : lookahead_(std::max<std::int64_t>(1, lookahead)) {}

  /// Whether a window ends with `tick`: what is queued must go to the links in this turn.
  bool window_ends(std::int64_t tick) const noexcept { return (tick + 1) % lookahead_ == 0; }

  /// Queues `messages`, sent in the turn `stamp`, for the link `link` (participant id
  /// `link_id`) to the node whose participant id is `peer_id`.
  void add(std::uint64_t link_id, const caf::actor& link, std::uint64_t peer_id, mail_stamp stamp,
           std::vector<protocol::net_message> messages) {
    auto it = std::find_if(queues_.begin(), queues_.end(),
                           [&](const queue& q) { return q.link_id == link_id; });
    if (it == queues_.end()) it = queues_.insert(queues_.end(), queue{link_id, link, peer_id, {}});
    // A flush hands the storage to the link: one allocation per window, not one per doubling.
    if (it->batches.empty()) it->batches.reserve(static_cast<std::size_t>(lookahead_));
    it->batches.push_back(net_send_batch{stamp, std::move(messages)});
  }

  /// Hands each link what is queued for it, as `(net_send_atom, int from, mail_stamp flushed,
  /// bool announced, batches)`. `flushed` is the turn this happens in. When `announced`, the
  /// link answers with one hand-over to the peer, and `on_relayed(peer_id)` is called for each
  /// link so that the caller announces it to the clock (`tick_context::relayed_to`). A flush
  /// outside a turn (a crash, the end of the run) is not announced.
  template <class Self, class OnRelayed>
  void flush(Self* self, int from, const mail_stamp& flushed, bool announced,
             OnRelayed on_relayed) {
    for (auto& q : queues_) {
      if (q.batches.empty()) continue;
      self->send(q.link, net_send_atom_v, from, flushed, announced, std::move(q.batches));
      q.batches.clear();
      if (announced) on_relayed(q.peer_id);
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
    std::uint64_t peer_id = 0;
    std::vector<net_send_batch> batches;
  };
  std::int64_t lookahead_;
  std::vector<queue> queues_;
};

}  // namespace argus::actors
