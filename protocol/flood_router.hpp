#pragma once

#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

#include "config/scenario.hpp"
#include "protocol/net_message.hpp"

namespace argus::protocol {

/// What a node does with one message: hand it to its own controller, and/or pass it on.
struct routing_decision {
  bool deliver = false;
  std::vector<int> forward_to;
};

/// Multi-hop delivery by flooding with duplicate suppression (docs/network.md).
///
/// A node forwards a message id to its live neighbours except the one it came from, while the
/// message has crossed fewer than `max_hops` links: the first time it sees the id, and again
/// only when a copy arrives over fewer hops than every earlier one. Link delays differ, so the
/// first copy may have come the long way round; were it the only one forwarded, a node three
/// hops out could be missed although a three-hop path exists. Hop counts only fall, so a
/// message costs at most `max_hops` transmissions per link direction — never a storm — and
/// every node within `max_hops` of the origin is reached when links lose nothing. A unicast whose
/// destination is a live neighbour goes over that one link only. A message that cannot reach its
/// destination within the hop limit is not delivered, as Table 2's "maximum number of hops" asks.
///
/// With reverse-path routing, a node also remembers, for every origin it has heard, the
/// neighbour that brought the origin's latest message over the fewest hops; a unicast to that
/// origin then goes to that neighbour alone, each relay doing the same, so an answer to a query
/// flooded over a thousand links crosses a handful instead of being flooded back. Cameras do
/// not move, so such a route stays good while its next hop is live; with none known, or its
/// next hop given up, the message is flooded as before. A single path has no spare copies:
/// each link's loss counts once per hop, where a flood often has another copy on the way.
class flood_router {
 public:
  /// The router of node `self`, routing unicasts by `unicast` and remembering the last
  /// `memory` message ids it has seen.
  explicit flood_router(int self, config::unicast_routing unicast = config::unicast_routing::flood,
                        std::size_t memory = 8192)
      : self_(self), memory_(memory), unicast_(unicast) {}

  /// A message this node sends; `live_neighbours` sorted.
  routing_decision originate(const net_message& m, const std::vector<int>& live_neighbours);

  /// A message that arrived over the link from neighbour `from` (its `hops` already counts
  /// that link); `live_neighbours` sorted.
  routing_decision receive(const net_message& m, int from, const std::vector<int>& live_neighbours);

  /// Copies dropped because this node had seen the message over as few hops before.
  std::uint64_t duplicates_suppressed() const noexcept { return duplicates_; }

 private:
  enum class sighting { first, fewer_hops, duplicate };
  sighting remember(std::uint64_t id, std::uint8_t hops);
  void learn_route(const net_message& m, int from);
  // The neighbour through which `origin`'s latest message came over the fewest hops, or 0.
  int route_to(int origin) const;
  std::vector<int> next_hops(const net_message& m, int from,
                             const std::vector<int>& live_neighbours) const;

  struct route {
    int via = 0;
    std::uint32_t seq = 0;
    std::uint8_t hops = 0;
  };

  int self_;
  std::size_t memory_;
  config::unicast_routing unicast_;
  std::unordered_map<int, route> routes_;                 // origin -> how its latest message came
  std::unordered_map<std::uint64_t, std::uint8_t> seen_;  // id -> fewest hops seen
  std::deque<std::uint64_t> seen_order_;
  std::uint64_t duplicates_ = 0;
};

}  // namespace argus::protocol
