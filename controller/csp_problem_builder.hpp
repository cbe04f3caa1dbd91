#pragma once

#include <vector>

#include "config/scenario.hpp"
#include "protocol/csp.hpp"
#include "protocol/group_messages.hpp"

namespace argus::controller {

/// One group of a centralised conflict: its task and leader.
struct csp_group_ref {
  protocol::task_id task = 0;
  int leader = 0;
};

/// A conflict between groups as a CSP (Section IV-B): what the solving leader gathered, mapped
/// to the solver's indices. Leaders stay with their groups and pinned members (joined less
/// than the minimum task duration ago) with theirs: neither is a variable's value, and each
/// lowers its group's minimum and maximum by one.
struct built_csp {
  protocol::csp_problem problem;
  /// The groups, in task order (the solver's group order).
  std::vector<csp_group_ref> groups;
  /// The cameras that can move, ascending (the solver's camera indices).
  std::vector<int> cameras;
  /// Each group's pinned members.
  std::vector<std::vector<int>> pinned;

  /// Group `g`'s cameras (besides its leader) under `solution`: its pinned members and the
  /// cameras the solver assigned it, ascending.
  std::vector<int> assigned(const protocol::csp_solution& solution, std::size_t g) const;
};

/// The CSP of `groups` (each leader's csp_data): a camera is in a group's domain when its
/// relevance to that group's task is at least `threshold`.
built_csp build_csp(std::vector<protocol::csp_data> groups, double threshold);

/// What a conflict's search may spend in a run: work only, so that the answer is the same on
/// every machine (a wall-clock budget is not), and small enough that a conflict among many
/// cameras never holds the clock up (bench/RESULTS.md, "The CSP within a budget"). Past it,
/// the best assignment found so far is applied and `csp_solved` says `"optimal":false`.
inline constexpr protocol::csp_limits run_csp_limits{
    .max_work = 200'000, .max_seconds = 0.0, .max_memory_bytes = std::size_t{64} << 20};

/// The solver a scenario names.
protocol::csp_solver_kind solver_kind(config::conflict_solver solver);

}  // namespace argus::controller
