#include "controller/csp_problem_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace argus::controller {
namespace {

double relevance_in(const std::vector<protocol::camera_relevance>& reported, int camera) {
  for (const auto& c : reported)
    if (c.camera == camera) return c.relevance;
  return -1.0;
}

}  // namespace

std::vector<int> built_csp::assigned(const protocol::csp_solution& solution, std::size_t g) const {
  std::vector<int> out = fixed[g];
  if (solution.solved && g < solution.assignment.size())
    for (auto index : solution.assignment[g]) out.push_back(cameras[index]);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<protocol::csp_assignment> built_csp::plan(
    const protocol::csp_solution& solution) const {
  std::vector<std::vector<int>> sets;
  for (std::size_t g = 0; g < groups.size(); ++g) sets.push_back(assigned(solution, g));
  // Each pass brings at least one leader home for good, so at most one pass per group.
  for (std::size_t pass = 0; pass <= groups.size(); ++pass) {
    bool changed = false;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (!sets[g].empty()) continue;
      for (auto& other : sets) std::erase(other, groups[g].leader);
      sets[g] = {groups[g].leader};
      changed = true;
    }
    if (!changed) break;
  }
  std::vector<protocol::csp_assignment> out;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const auto& set = sets[g];
    int leader = groups[g].leader;
    if (std::find(set.begin(), set.end(), leader) == set.end()) {
      leader = set.front();
      for (int c : set)
        if (relevance_in(reported[g], c) > relevance_in(reported[g], leader)) leader = c;
    }
    protocol::csp_assignment a;
    a.task = groups[g].task;
    a.leader = leader;
    a.term = leader == groups[g].leader ? groups[g].term : groups[g].term + 1;
    a.previous = groups[g].leader;
    a.relevance = std::max(0.0, relevance_in(reported[g], leader));
    for (int c : set)
      if (c != leader) a.members.push_back({c, std::max(0.0, relevance_in(reported[g], c))});
    const auto taken = fixed[g].size();
    const unsigned minimum = g < solution.minima.size() ? solution.minima[g] : 0u;
    a.minimum = static_cast<std::uint16_t>(minimum + taken);
    out.push_back(std::move(a));
  }
  return out;
}

built_csp build_csp(std::vector<protocol::csp_data> groups, double threshold, double stay_bonus) {
  std::stable_sort(groups.begin(), groups.end(),
                   [](const auto& a, const auto& b) { return a.task.task < b.task.task; });
  groups.erase(std::unique(groups.begin(), groups.end(),
                           [](const auto& a, const auto& b) { return a.task.task == b.task.task; }),
               groups.end());
  built_csp out;
  std::set<int> staying;
  for (const auto& g : groups) {
    std::vector<protocol::camera_relevance> reported;
    for (const auto& c : g.candidates) {
      auto it = std::find_if(reported.begin(), reported.end(),
                             [&](const auto& r) { return r.camera == c.camera; });
      if (it == reported.end()) {
        reported.push_back(c);
      } else {
        it->relevance = std::max(it->relevance, c.relevance);
      }
    }
    std::vector<int> fixed;
    for (int p : g.pinned)
      if (staying.insert(p).second) fixed.push_back(p);
    const bool leader_sees = relevance_in(reported, g.leader) >= threshold;
    if ((!leader_sees || std::count(g.pinned.begin(), g.pinned.end(), g.leader) != 0) &&
        std::find(fixed.begin(), fixed.end(), g.leader) == fixed.end() &&
        staying.insert(g.leader).second)
      fixed.push_back(g.leader);
    std::sort(fixed.begin(), fixed.end());
    out.groups.push_back({g.task, g.leader, g.term});
    out.fixed.push_back(std::move(fixed));
    out.reported.push_back(std::move(reported));
  }
  std::set<int> movable;
  for (const auto& reported : out.reported)
    for (const auto& c : reported)
      if (staying.count(c.camera) == 0) movable.insert(c.camera);
  out.cameras.assign(movable.begin(), movable.end());
  out.problem.camera_count = out.cameras.size();
  out.problem.threshold = threshold;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const auto taken = static_cast<unsigned>(out.fixed[g].size());
    const unsigned min = groups[g].task.min_cameras, max = groups[g].task.max_cameras;
    protocol::csp_group group;
    group.min_cameras = min > taken ? min - taken : 0;
    group.max_cameras = max > taken ? max - taken : 0;
    group.relevance.assign(out.cameras.size(), std::numeric_limits<double>::quiet_NaN());
    const auto& members = groups[g].members;
    for (const auto& c : out.reported[g]) {
      auto it = std::lower_bound(out.cameras.begin(), out.cameras.end(), c.camera);
      if (it == out.cameras.end() || *it != c.camera) continue;
      const bool stays = c.relevance >= threshold &&
                         std::find(members.begin(), members.end(), c.camera) != members.end();
      group.relevance[static_cast<std::size_t>(it - out.cameras.begin())] =
          c.relevance + (stays ? stay_bonus : 0.0);
    }
    out.problem.groups.push_back(std::move(group));
  }
  return out;
}

protocol::csp_solver_kind solver_kind(config::conflict_solver solver) {
  return protocol::solver_kind_of(solver);  // one mapping, where the solvers are
}

}  // namespace argus::controller
