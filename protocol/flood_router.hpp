#pragma once

#include <cstdint>
#include <deque>
#include <unordered_set>
#include <vector>

#include "protocol/net_message.hpp"

namespace argus::protocol {

/// What a node does with one message: hand it to its own controller, and/or pass it on.
struct routing_decision {
  bool deliver = false;
  std::vector<int> forward_to;
};

/// Multi-hop delivery by flooding with duplicate suppression (docs/network.md).
///
/// A node forwards each message id at most once, to its live neighbours except the one it
/// came from, while the message has crossed fewer than `max_hops` links; so one message costs
/// at most one transmission per link, never a storm. A unicast whose destination is a live
/// neighbour goes over that one link only. A message that cannot reach its destination within
/// the hop limit is not delivered, as Table 2's "maximum number of hops" asks.
class flood_router {
 public:
  /// The router of node `self`, remembering the last `memory` message ids it has seen.
  explicit flood_router(int self, std::size_t memory = 8192) : self_(self), memory_(memory) {}

  /// A message this node sends; `live_neighbours` sorted.
  routing_decision originate(const net_message& m, const std::vector<int>& live_neighbours);

  /// A message that arrived over the link from neighbour `from` (its `hops` already counts
  /// that link); `live_neighbours` sorted.
  routing_decision receive(const net_message& m, int from, const std::vector<int>& live_neighbours);

  /// Messages dropped because this node had seen them before.
  std::uint64_t duplicates_suppressed() const noexcept { return duplicates_; }

 private:
  bool remember(std::uint64_t id);
  std::vector<int> next_hops(const net_message& m, int from,
                             const std::vector<int>& live_neighbours) const;

  int self_;
  std::size_t memory_;
  std::unordered_set<std::uint64_t> seen_;
  std::deque<std::uint64_t> seen_order_;
  std::uint64_t duplicates_ = 0;
};

}  // namespace argus::protocol
