#include "controller/csp_problem_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace argus::controller {

std::vector<int> built_csp::assigned(const protocol::csp_solution& solution, std::size_t g) const {
  std::vector<int> out = pinned[g];
  if (solution.solved && g < solution.assignment.size())
    for (auto index : solution.assignment[g]) out.push_back(cameras[index]);
  std::sort(out.begin(), out.end());
  return out;
}

built_csp build_csp(std::vector<protocol::csp_data> groups, double threshold) {
  std::sort(groups.begin(), groups.end(),
            [](const auto& a, const auto& b) { return a.task < b.task; });
  groups.erase(std::unique(groups.begin(), groups.end(),
                           [](const auto& a, const auto& b) { return a.task == b.task; }),
               groups.end());
  std::set<int> fixed;  // leaders and pinned members
  for (const auto& g : groups) {
    fixed.insert(g.leader);
    fixed.insert(g.pinned.begin(), g.pinned.end());
  }
  std::set<int> movable;
  for (const auto& g : groups)
    for (const auto& c : g.candidates)
      if (fixed.count(c.camera) == 0) movable.insert(c.camera);

  built_csp out;
  out.cameras.assign(movable.begin(), movable.end());
  out.problem.camera_count = out.cameras.size();
  out.problem.threshold = threshold;
  for (const auto& g : groups) {
    out.groups.push_back({g.task, g.leader});
    std::vector<int> pinned;
    for (int p : g.pinned)
      if (p != g.leader) pinned.push_back(p);
    std::sort(pinned.begin(), pinned.end());
    const unsigned taken = 1 + static_cast<unsigned>(pinned.size());
    protocol::csp_group group;
    group.min_cameras = g.min_cameras > taken ? g.min_cameras - taken : 0;
    group.max_cameras = g.max_cameras > taken ? g.max_cameras - taken : 0;
    group.relevance.assign(out.cameras.size(), std::numeric_limits<double>::quiet_NaN());
    for (const auto& c : g.candidates) {
      auto it = std::lower_bound(out.cameras.begin(), out.cameras.end(), c.camera);
      if (it == out.cameras.end() || *it != c.camera) continue;
      auto& r = group.relevance[static_cast<std::size_t>(it - out.cameras.begin())];
      if (std::isnan(r) || c.relevance > r) r = c.relevance;
    }
    out.problem.groups.push_back(std::move(group));
    out.pinned.push_back(std::move(pinned));
  }
  return out;
}

protocol::csp_solver_kind solver_kind(config::conflict_solver solver) {
  return protocol::solver_kind_of(solver);  // one mapping, where the solvers are
}

}  // namespace argus::controller
