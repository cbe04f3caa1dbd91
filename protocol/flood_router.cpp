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

std::vector<int> flood_router::next_hops(const net_message& m, int from,
                                         const std::vector<int>& live_neighbours) const {
  if (m.hops >= m.max_hops) return {};
  if (m.destination != broadcast &&
      std::binary_search(live_neighbours.begin(), live_neighbours.end(), m.destination))
    return {m.destination};
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
  // A shorter copy is passed on again, but its controller has it already.
  d.deliver = seen == sighting::first && (m.destination == broadcast || m.destination == self_);
  if (m.destination != self_) d.forward_to = next_hops(m, from, live_neighbours);
  return d;
}

}  // namespace argus::protocol
