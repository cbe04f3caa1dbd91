#include "protocol/flood_router.hpp"

#include <algorithm>

namespace argus::protocol {

flood_router::sighting flood_router::remember(std::uint64_t id, std::uint8_t hops) {
  auto [it, inserted] = seen_.try_emplace(id, hops);
  if (!inserted) {
    if (hops >= it->second) return sighting::duplicate;
    it->second = hops;
    return sighting::fewer_hops;
  }
  seen_order_.push_back(id);
  if (seen_order_.size() > memory_) {
    seen_.erase(seen_order_.front());
    seen_order_.pop_front();
  }
  return sighting::first;
}

// A newer message from the origin replaces the route (the older one may lead through a node
// that has since failed); a copy of the same message over fewer hops shortens it.
void flood_router::learn_route(const net_message& m, int from) {
  if (unicast_ != config::unicast_routing::reverse_path || m.origin == self_) return;
  const auto seq = static_cast<std::uint32_t>(m.id);
  auto [it, inserted] = routes_.try_emplace(m.origin, route{from, seq, m.hops});
  if (inserted) return;
  route& r = it->second;
  if (seq > r.seq || (seq == r.seq && m.hops < r.hops)) r = route{from, seq, m.hops};
}

int flood_router::route_to(int origin) const {
  const auto it = routes_.find(origin);
  return it == routes_.end() ? 0 : it->second.via;
}

std::vector<int> flood_router::next_hops(const net_message& m, int from,
                                         const std::vector<int>& live_neighbours) const {
  if (m.hops >= m.max_hops) return {};
  const auto live = [&](int n) {
    return std::binary_search(live_neighbours.begin(), live_neighbours.end(), n);
  };
  if (m.destination != broadcast) {
    if (live(m.destination)) return {m.destination};
    const int via = route_to(m.destination);
    if (via != 0 && via != from && live(via)) return {via};
  }
  std::vector<int> out;
  for (int n : live_neighbours)
    if (n != from && n != m.origin) out.push_back(n);
  return out;
}

routing_decision flood_router::originate(const net_message& m,
                                         const std::vector<int>& live_neighbours) {
  remember(m.id, m.hops);
  routing_decision d;
  d.deliver = false;
  d.forward_to = next_hops(m, self_, live_neighbours);
  return d;
}

routing_decision flood_router::receive(const net_message& m, int from,
                                       const std::vector<int>& live_neighbours) {
  routing_decision d;
  auto seen = remember(m.id, m.hops);
  if (seen == sighting::duplicate) {
    ++duplicates_;
    return d;
  }
  learn_route(m, from);
  // A shorter copy is passed on again, but its controller has it already.
  d.deliver = seen == sighting::first && (m.destination == broadcast || m.destination == self_);
  if (m.destination != self_) d.forward_to = next_hops(m, from, live_neighbours);
  return d;
}

}  // namespace argus::protocol
