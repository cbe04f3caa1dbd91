#pragma once

#include <vector>

#include "config/scenario.hpp"
#include "protocol/csp.hpp"
#include "protocol/group_messages.hpp"

namespace argus::controller {

/// One group of a centralised conflict: its task, its leader and the leadership's epoch.
struct csp_group_ref {
  protocol::task_description task;
  int leader = 0;
  protocol::term_epoch term = 0;
};

/// A conflict between groups as a CSP (Section IV-B): what the solving leader gathered, mapped
/// to the solver's indices. Every camera a group reported with its relevance is a value of the
/// group's variable, its leader included (Fig. 19: the two cameras decide between them which
/// carries which task). What stays where it is, lowering its group's minimum and maximum by
/// one: a camera `pinned` by its group (placed there by a conflict's result less than the
/// minimum task duration ago, Table 2), and a leader that does not see its own target above
/// the threshold (moved away, it would leave its group with nobody who knows it).
struct built_csp {
  protocol::csp_problem problem;
  /// The groups, in task order (the solver's group order).
  std::vector<csp_group_ref> groups;
  /// The cameras that can move, ascending (the solver's camera indices).
  std::vector<int> cameras;
  /// The cameras that stay in each group (ascending).
  std::vector<std::vector<int>> fixed;
  /// Each group's relevance of every camera it reported (camera -> relevance).
  std::vector<std::vector<protocol::camera_relevance>> reported;

  /// Group `g`'s cameras under `solution`: those that stay and those the solver assigned it,
  /// ascending.
  std::vector<int> assigned(const protocol::csp_solution& solution, std::size_t g) const;
  /// The result to send: each group's cameras under `solution`, led by its leader if it stays
  /// in the group, else by the most relevant of them (ties: the lowest id) at a new epoch. A
  /// group the solution leaves with no camera keeps its leader, taken back from the group it
  /// was assigned to: a conflict never ends a task.
  std::vector<protocol::csp_assignment> plan(const protocol::csp_solution& solution) const;
};

/// The CSP of `groups` (each leader's csp_data): a camera is in a group's domain when its
/// relevance to that group's task is at least `threshold`. A group reported twice counts once
/// (the first); a camera reported twice by one group counts with its highest relevance.
/// `stay_bonus` is added to the relevance of each camera to the group it is in
/// (controller.conflict_stay_bonus; the domain is decided before it is added).
built_csp build_csp(std::vector<protocol::csp_data> groups, double threshold,
                    double stay_bonus = 0.0);

/// What a conflict's search may spend in a run: work only, so that the answer is the same on
/// every machine (a wall-clock budget is not), and small enough that a conflict among many
/// cameras never holds the clock up (bench/RESULTS.md, "The CSP within a budget"). Past it,
/// the best assignment found so far is applied and `csp_solved` says `"optimal":false`.
inline constexpr protocol::csp_limits run_csp_limits{
    .max_work = 200'000, .max_seconds = 0.0, .max_memory_bytes = std::size_t{64} << 20};

/// The solver a scenario names.
protocol::csp_solver_kind solver_kind(config::conflict_solver solver);

}  // namespace argus::controller
