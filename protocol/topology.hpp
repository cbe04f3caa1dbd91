#pragma once

#include <map>
#include <utility>
#include <vector>

#include "config/scenario.hpp"

namespace argus::protocol {

/// Which camera nodes are neighbours: the scenario's explicit `network.adjacency` if it has
/// one, else every pair within `network.communication_range_m` on the floor plan. Built by the
/// simulator from positions the nodes themselves never see.
class topology {
 public:
  /// Builds the neighbour graph of a scenario's cameras.
  explicit topology(const config::scenario& scenario);

  /// Every link as (smaller id, larger id), sorted.
  const std::vector<std::pair<int, int>>& links() const noexcept { return links_; }

  /// The neighbours of `node`, sorted; empty for an unknown node.
  const std::vector<int>& neighbours(int node) const;

  /// Node ids, sorted.
  std::vector<int> nodes() const;

  /// Nodes reachable from `from` in at most `max_hops` links (excluding `from`), over the
  /// links for which `up(a, b)` is true.
  template <class LinkUp>
  std::vector<int> within_hops(int from, unsigned max_hops, LinkUp up) const;

 private:
  std::vector<std::pair<int, int>> links_;
  std::map<int, std::vector<int>> neighbours_;
};

template <class LinkUp>
std::vector<int> topology::within_hops(int from, unsigned max_hops, LinkUp up) const {
  std::map<int, unsigned> depth{{from, 0}};
  std::vector<int> frontier{from};
  for (unsigned d = 1; d <= max_hops && !frontier.empty(); ++d) {
    std::vector<int> next;
    for (int n : frontier)
      for (int m : neighbours(n))
        if (up(n, m) && depth.emplace(m, d).second) next.push_back(m);
    frontier = std::move(next);
  }
  std::vector<int> out;
  for (const auto& [node, d] : depth)
    if (node != from) out.push_back(node);
  return out;
}

}  // namespace argus::protocol
