#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "actors/net_send_window.hpp"
#include "actors/send_unattributed.hpp"
#include "actors/type_ids.hpp"

namespace argus::actors {

/// A node's outgoing side of its links. What the node sends on a link in one turn is queued
/// here and handed to the link once per lookahead window, as one CAF message holding every
/// turn's messages with the tick it was sent at (docs/network.md, "Outbox").
///
/// Windows are aligned to the tick grid: a window ends at each tick t with (t + 1) % L == 0.
/// Nothing sent in a window is due before the tick after it ends (L is the minimum delay), so
/// a link that hands everything over as soon as it reads it is always in time.
class link_outbox {
 public:
  explicit link_outbox(std::int64_t lookahead) : lookahead_(std::max<std::int64_t>(1, lookahead)) {}

  /// Whether a window ends with `tick`: what is queued must go to the links in this turn.
  bool window_ends(std::int64_t tick) const noexcept { return (tick + 1) % lookahead_ == 0; }

  /// Queues `message`, sent at tick `sent`, for the link `link` (participant id `link_id`) to
  /// the node whose participant id is `peer_id`.
  void add(std::uint64_t link_id, const caf::actor& link, std::uint64_t peer_id, std::int64_t sent,
           protocol::net_message message) {
    queue_for(link_id, link, peer_id).window.add(sent, std::move(message));
  }

  /// Queues `messages`, all sent at tick `sent`, for the link `link`.
  void add(std::uint64_t link_id, const caf::actor& link, std::uint64_t peer_id, std::int64_t sent,
           std::vector<protocol::net_message> messages) {
    auto& q = queue_for(link_id, link, peer_id);
    for (auto& m : messages) q.window.add(sent, std::move(m));
  }

  /// Hands each link what is queued for it, as a `net_send_mail` from end `from`. `flushed` is the
  /// turn this happens in. When `announced`, the link answers with one hand-over to the peer, and
  /// `on_relayed(peer_id)` is called for each link so that the caller announces it to the clock
  /// (`tick_context::relayed_to`). A flush outside a turn (a crash, the end of the run) is not
  /// announced.
  template <class Self, class OnRelayed>
  void flush(Self* self, int from, const mail_stamp& flushed, bool announced,
             OnRelayed on_relayed) {
    for (auto& q : queues_) {
      if (q.window.empty()) continue;
      q.last_size = static_cast<std::uint32_t>(q.window.messages.size());
      send_unattributed(self, q.link, net_send_mail{from, flushed, announced, std::move(q.window)});
      q.window = net_send_window{};
      if (announced) on_relayed(q.peer_id);
    }
  }

  /// Whether nothing is queued.
  bool empty() const noexcept {
    return std::all_of(queues_.begin(), queues_.end(),
                       [](const queue& q) { return q.window.empty(); });
  }

 private:
  struct queue {
    std::uint64_t link_id = 0;
    caf::actor link;
    std::uint64_t peer_id = 0;
    std::uint32_t last_size = 0;  // of the last window sent: this one is likely alike
    net_send_window window;
  };

  queue& queue_for(std::uint64_t link_id, const caf::actor& link, std::uint64_t peer_id) {
    if (last_ >= queues_.size() || queues_[last_].link_id != link_id) {
      auto it = std::find_if(queues_.begin(), queues_.end(),
                             [&](const queue& q) { return q.link_id == link_id; });
      if (it == queues_.end())
        it = queues_.insert(queues_.end(), queue{link_id, link, peer_id, 0, {}});
      last_ = static_cast<std::size_t>(it - queues_.begin());
    }
    auto& q = queues_[last_];
    // The window's storage goes to the link with it: size it once, not once per doubling.
    if (q.window.messages.capacity() == 0) {
      q.window.messages.reserve(std::max<std::uint32_t>(q.last_size, 1));
      q.window.ticks.reserve(static_cast<std::size_t>(lookahead_));
    }
    return q;
  }

  std::int64_t lookahead_;
  std::vector<queue> queues_;
  std::size_t last_ = 0;  // the queue added to last: sends come a link at a time
};

}  // namespace argus::actors
