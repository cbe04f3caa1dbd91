#include "protocol/topology.hpp"

#include <algorithm>
#include <cmath>

namespace argus::protocol {

topology::topology(const config::scenario& scenario) {
  for (const auto& cam : scenario.cameras) neighbours_[cam.id];
  if (!scenario.network.adjacency.empty()) {
    for (const auto& pair : scenario.network.adjacency)
      links_.emplace_back(std::min(pair[0], pair[1]), std::max(pair[0], pair[1]));
  } else {
    const auto range = scenario.network.communication_range_m;
    const auto& cams = scenario.cameras;
    for (std::size_t i = 0; i < cams.size(); ++i)
      for (std::size_t j = i + 1; j < cams.size(); ++j) {
        auto dx = cams[i].position.x_m - cams[j].position.x_m;
        auto dy = cams[i].position.y_m - cams[j].position.y_m;
        if (std::hypot(dx, dy) <= range)
          links_.emplace_back(std::min(cams[i].id, cams[j].id), std::max(cams[i].id, cams[j].id));
      }
  }
  std::sort(links_.begin(), links_.end());
  links_.erase(std::unique(links_.begin(), links_.end()), links_.end());
  for (const auto& [a, b] : links_) {
    neighbours_[a].push_back(b);
    neighbours_[b].push_back(a);
  }
  for (auto& [node, list] : neighbours_) std::sort(list.begin(), list.end());
}

const std::vector<int>& topology::neighbours(int node) const {
  static const std::vector<int> none;
  auto it = neighbours_.find(node);
  return it == neighbours_.end() ? none : it->second;
}

std::vector<int> topology::nodes() const {
  std::vector<int> out;
  for (const auto& [node, list] : neighbours_) out.push_back(node);
  return out;
}

}  // namespace argus::protocol
