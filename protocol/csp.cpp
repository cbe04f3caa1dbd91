#include "protocol/csp.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "config/scenario.hpp"
#include "fmt/format.h"
#include "protocol/csp_search.hpp"

namespace argus::protocol {
namespace {

void validate(const csp_problem& problem) {
  if (!(problem.threshold >= 0.0))
    throw std::invalid_argument(
        fmt::format("csp: threshold must be a non-negative number, got {}", problem.threshold));
  for (std::size_t g = 0; g < problem.groups.size(); ++g) {
    const auto& group = problem.groups[g];
    if (group.min_cameras > group.max_cameras)
      throw std::invalid_argument(
          fmt::format("csp: group {}: min_cameras {} exceeds max_cameras {}", g, group.min_cameras,
                      group.max_cameras));
    if (group.relevance.size() > problem.camera_count)
      throw std::invalid_argument(fmt::format("csp: group {}: {} relevances for {} cameras", g,
                                              group.relevance.size(), problem.camera_count));
    for (std::size_t c = 0; c < group.relevance.size(); ++c)
      if (std::isinf(group.relevance[c]))
        throw std::invalid_argument(
            fmt::format("csp: group {}: relevance of camera {} is infinite", g, c));
  }
}

/// Lowers one minimum by one, by the order stated in csp.hpp ("Relaxation"); false when every
/// minimum is already 0.
bool lower_one_minimum(std::vector<unsigned>& minima,
                       const std::vector<std::vector<std::size_t>>& relevant) {
  const std::size_t count = minima.size();
  // 1. A group that cannot be served whatever the others do, the highest index.
  for (std::size_t g = count; g-- > 0;) {
    if (minima[g] > relevant[g].size()) {
      --minima[g];
      return true;
    }
  }
  // 2. The largest minimum of 2 or more, ties by highest index.
  std::size_t chosen = count;
  for (std::size_t g = 0; g < count; ++g)
    if (minima[g] >= 2 && (chosen == count || minima[g] >= minima[chosen])) chosen = g;
  // 3. Else a minimum of 1: the group with the fewest relevant cameras, ties by highest index.
  if (chosen == count)
    for (std::size_t g = 0; g < count; ++g)
      if (minima[g] == 1 && (chosen == count || relevant[g].size() <= relevant[chosen].size()))
        chosen = g;
  if (chosen == count) return false;
  --minima[chosen];
  return true;
}

csp_search::outcome search(const csp_search::round_problem& round, csp_solver_kind solver) {
  using csp_search::lexicographic_pruning;
  switch (solver) {
    case csp_solver_kind::all_solv:
      return csp_search::lexicographic_search(round, lexicographic_pruning::none);
    case csp_solver_kind::best_solv:
      return csp_search::lexicographic_search(round, lexicographic_pruning::paper);
    case csp_solver_kind::optimistic_solv:
      return csp_search::lexicographic_search(round, lexicographic_pruning::optimistic);
    case csp_solver_kind::bound_solv:
      return csp_search::bound_search(round);
  }
  throw std::invalid_argument("csp: unknown solver");
}

/// The answer of a search stopped before it found any complete assignment (csp.hpp,
/// "Budgets"): each group in index order takes its most relevant free cameras, up to its
/// maximum; a group that gets fewer than its minimum has the minimum lowered to what it got.
void assign_greedily(const csp_problem& problem,
                     const std::vector<std::vector<std::size_t>>& relevant,
                     csp_solution& solution) {
  std::vector<char> taken(problem.camera_count, 0);
  solution.assignment.assign(problem.groups.size(), {});
  solution.weight = 0.0;
  for (std::size_t g = 0; g < problem.groups.size(); ++g) {
    auto order = relevant[g];
    const auto& relevance = problem.groups[g].relevance;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return relevance[a] > relevance[b]; });
    auto& mine = solution.assignment[g];
    for (std::size_t c : order) {
      if (mine.size() >= problem.groups[g].max_cameras) break;
      if (taken[c]) continue;
      taken[c] = 1;
      mine.push_back(c);
    }
    std::sort(mine.begin(), mine.end());
    if (mine.size() < solution.minima[g]) {
      solution.minima[g] = static_cast<unsigned>(mine.size());
      solution.relaxed = true;
    }
  }
  for (std::size_t g = 0; g < solution.assignment.size(); ++g)  // the canonical order
    for (std::size_t c : solution.assignment[g]) solution.weight += problem.groups[g].relevance[c];
  solution.solved = true;
}

}  // namespace

csp_solver_kind solver_kind_of(config::conflict_solver solver) {
  switch (solver) {
    case config::conflict_solver::all_solv:
      return csp_solver_kind::all_solv;
    case config::conflict_solver::best_solv:
      return csp_solver_kind::best_solv;
    case config::conflict_solver::optimistic_solv:
      return csp_solver_kind::optimistic_solv;
    case config::conflict_solver::bound_solv:
      return csp_solver_kind::bound_solv;
  }
  throw std::invalid_argument("csp: unknown conflict_solver");
}

const char* stop_name(csp_stop stop) noexcept {
  switch (stop) {
    case csp_stop::none:
      return "";
    case csp_stop::work:
      return "work";
    case csp_stop::time:
      return "time";
    case csp_stop::memory:
      return "memory";
  }
  return "";
}

csp_solution solve(const csp_problem& problem, csp_solver_kind solver, const csp_limits& limits) {
  validate(problem);
  const auto relevant = csp_search::relevant_cameras(problem);
  csp_search::search_budget budget(limits);
  csp_solution solution;
  for (const auto& group : problem.groups) solution.minima.push_back(group.min_cameras);
  while (true) {
    const auto found = search({problem, solution.minima, relevant, budget}, solver);
    solution.nodes_explored += found.nodes_explored;
    solution.backtracks += found.backtracks;
    solution.solutions += found.solutions;
    solution.stopped_by = budget.reason();
    if (found.found) {
      solution.solved = true;
      solution.assignment = found.best;
      solution.weight = found.weight;
      solution.complete = !budget.stopped();
      solution.proven_optimal = solution.complete && is_exact(solver);
      if (!solution.complete) {
        // A search cut short may hold little more than its first complete assignment (the
        // lexicographic ones especially): the greedy one, if it meets the same minima and is
        // heavier, is the better answer found.
        csp_solution greedy = solution;
        greedy.relaxed = false;
        assign_greedily(problem, relevant, greedy);
        if (!greedy.relaxed && greedy.weight > solution.weight) {
          solution.assignment = std::move(greedy.assignment);
          solution.weight = greedy.weight;
        }
      }
      return solution;
    }
    if (budget.stopped()) {  // no answer found in time: not proof that there is none
      assign_greedily(problem, relevant, solution);
      return solution;
    }
    if (!lower_one_minimum(solution.minima, relevant)) return solution;
    solution.relaxed = true;
  }
}

}  // namespace argus::protocol
