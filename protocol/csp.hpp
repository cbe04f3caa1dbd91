#pragma once

// Group-group conflict resolution as a constraint satisfaction problem (Section IV-B, Fig. 14,
// Table 1). Plain C++, no CAF: the supervisor that centralises a conflict builds a
// `csp_problem` from the relevances it gathered and calls `solve`.
//
// The problem. Each group g is a variable. Its domain is every set S of its relevant cameras
// (relevance >= threshold, NaN never relevant) with min_cameras(g) <= |S| <= max_cameras(g);
// the empty set belongs to the domain only when the minimum is 0. Constraint C_ij (Fig. 14):
// no camera is assigned to two groups. Objective: maximise the weight, the sum of the
// relevances of the assigned cameras, computed in one canonical order (groups in index order,
// each group's cameras ascending) so that every solver gets the same double for the same
// assignment. Ties (equal weights, exactly) go to the lexicographically smallest assignment:
// the sequence of the groups' camera lists in group order, each list ascending, compared
// element by element as `std::vector<std::vector<std::size_t>>` compares.
//
// The solvers. all_solv, optimistic_solv and bound_solv are exact: they return the same optimum
// and the same tie-broken assignment. best_solv is the paper's rule, which is exact only under
// an assumption the objective does not meet (below).
//  - all_solv: the paper's naive backtracking. Groups in index order, each domain enumerated
//    in lexicographic order; every complete consistent assignment is reached and compared
//    with the best so far (ranking them all without storing them).
//  - best_solv: the paper's BestSolv as Section IV-B states it: "we store the currently best
//    result and backtrack whenever the current partial solution is of poorer quality". The
//    same search as all_solv; a partial assignment of groups 0..g is dropped when its weight
//    is below the weight of the best complete assignment's own groups 0..g (the best result
//    taken to the same depth: the only like-for-like comparison a partial solution has), and
//    a complete one when it is below the best. The paper guarantees the optimum "under the
//    assumption that the quality of solutions increase monotonically as values are assigned";
//    with a shared camera, a partial solution that is poorer so far can still end heavier
//    (its groups left the better cameras to the later ones), so this search can miss the
//    optimum: on Table 1's instances it does on 11 % and 7 % of them, by under 2 % of the
//    weight when it does (bench/RESULTS.md). Its answers are never flagged proven optimal.
//  - optimistic_solv (beyond the paper; BestSolv made exact): the same search, but a partial
//    assignment is dropped when its weight plus an optimistic completion cannot reach the
//    best complete weight found so far. The completion bound is static: for each unassigned
//    group, the sum of its max_cameras largest relevances, ignoring which cameras are already
//    taken. Runs default to it.
//  - bound_solv (beyond the paper): branch and bound with
//      * a dynamic bound: for the unassigned groups R over the still free cameras F,
//        min(sum over g in R of the sum of g's max_cameras largest relevances on F,
//            the sum of the (sum over R of max_cameras) largest values, over c in F, of
//            max over g in R of relevance_g(c)),
//        both valid because a camera serves one group at most;
//      * forward checking: a value is dropped when an unassigned group has fewer free
//        relevant cameras than its minimum;
//      * values in nonincreasing order of their total, weight plus the bound above after
//        taking them (best first within the depth-first search). They are generated lazily
//        from the free cameras, heaviest first, only while an ungenerated one could still
//        have the largest total; generation stops for good at the first value whose weight
//        plus the bound before the group's assignment cannot reach the best;
//      * variables most constrained first: at each node, the unassigned group with the fewest
//        candidate values (sum over sizes s of C(free relevant cameras, s)), ties by index.
//    A value is dropped only when it cannot reach the best weight by more than 1e-9 (far
//    beyond rounding), so exact ties are always searched and settled by the leaf rule above.
//
// Budgets. A search stops when it has generated `max_work` values (each counted as a
// backtrack below; deterministic, the limit runs use), after `max_seconds` of wall time (checked
// every 1,024 values; for the command line, never in a run), or when the values bound_solv holds
// in memory would pass `max_memory_bytes`. A stopped search returns, with `complete` false,
// the best complete assignment it found or the greedy one (each group in index order takes its
// most relevant free cameras), whichever is heavier; the greedy one only if it meets the same
// minima, unless the search found none (then minima are lowered to what each group got). The
// relaxation rounds share one budget. bound_solv also keeps at most 4,096 generated values
// waiting per group before it searches one, so its memory grows with the depth, not the domain.
//
// Counting (one definition, counted the same way by every solver, and the one that
// reproduces Table 1's AllSolv figures exactly: 29511 = 1 + 220 + 29290 nodes,
// 48620 = 220 x 221 backtracks; its BestSolv figures fit it too: 36520 = 220 x 166 backtracks
// and 175 = 1 + 165 + 9 nodes, 165 first-group values kept and 9 solutions):
//  - nodes_explored: the root of each search, plus every value the search assigns to a group
//    and keeps: it shares no camera with the groups assigned before it and passes the
//    solver's pruning test (all_solv has none). Complete assignments are nodes too.
//  - backtracks: every candidate value a solver generates for a group and then takes back,
//    whatever the reason: it clashed with an earlier group, failed the pruning test, or its
//    subtree (or complete assignment) was searched. all_solv and best_solv generate every
//    domain value under each kept parent; bound_solv generates values from free cameras only
//    and lazily (see above), so the values it never generates are not counted.
//    optimistic_solv counts as best_solv does.
//  - solutions: complete assignments kept as nodes (all_solv: every consistent complete
//    assignment, Table 1's "number of solutions"; the others: those that passed the pruning).
//
// Relaxation (the paper's "relaxing the node requirements for each task"). When the minima
// admit no assignment at all, they are lowered one step per round, and the search re-run,
// until one exists. Each round lowers by one the minimum of one group, the first rule that
// applies choosing it:
//  1. a group whose minimum exceeds its number of relevant cameras (it cannot be served
//     whatever the others do), the highest index among them;
//  2. else a group with a minimum of 2 or more: the largest minimum, ties by highest index;
//  3. else (every minimum is 0 or 1) a group with minimum 1: the one with the fewest relevant
//     cameras, ties by highest index.
// So no minimum goes from 1 to 0 while another is above 1, unless the group has no relevant
// camera at all. With every minimum 0 the empty assignment is always a solution, so solve
// always succeeds. Relaxation happens only when the given minima admit no assignment.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "config/fwd.hpp"

namespace argus::protocol {

/// Which search settles the conflict: the paper's AllSolv and BestSolv, or ours,
/// optimistic_solv (BestSolv with a sound bound) and bound_solv.
enum class csp_solver_kind { all_solv, best_solv, optimistic_solv, bound_solv };

/// Whether the solver returns the optimum whenever its search completes (all but best_solv).
constexpr bool is_exact(csp_solver_kind solver) noexcept {
  return solver != csp_solver_kind::best_solv;
}

/// What a search may spend (see "Budgets" above); 0 means no limit. The defaults bound memory
/// only.
struct csp_limits {
  std::uint64_t max_work = 0;
  double max_seconds = 0.0;
  std::size_t max_memory_bytes = std::size_t{256} << 20;
};

/// Why a search stopped before its end.
enum class csp_stop { none, work, time, memory };

/// The solver a scenario's `controller.solver` names.
csp_solver_kind solver_kind_of(config::conflict_solver solver);

/// One group (variable). relevance[i] is camera i's relevance to this group's task; a camera
/// with relevance < problem.threshold (or NaN), or beyond the end of the vector, is not in the
/// group's domain.
struct csp_group {
  unsigned min_cameras = 1;
  unsigned max_cameras = 1;
  std::vector<double> relevance;
};

/// Groups in id order; cameras are indices 0..camera_count-1 in id order (callers map ids).
struct csp_problem {
  std::vector<csp_group> groups;
  std::size_t camera_count = 0;
  double threshold = 0.1;
};

/// The answer of `solve`, with the search's effort.
struct csp_solution {
  /// False only if even all-zero minima fail, which cannot happen.
  bool solved = false;
  /// Per group, camera indices ascending.
  std::vector<std::vector<std::size_t>> assignment;
  /// Sum of the relevances of the assigned cameras (canonical order, see above).
  double weight = 0.0;
  /// The minima the answer meets (the groups' own unless relaxed).
  std::vector<unsigned> minima;
  /// Whether any minimum was lowered.
  bool relaxed = false;
  /// Whether every search ran to its end (no budget ran out).
  bool complete = false;
  /// Whether the answer is proven optimal: complete, by an exact solver.
  bool proven_optimal = false;
  /// The budget that ran out, if one did.
  csp_stop stopped_by = csp_stop::none;
  /// Search effort, summed over all relaxation rounds (definitions above).
  std::uint64_t nodes_explored = 0;
  std::uint64_t backtracks = 0;
  std::uint64_t solutions = 0;
};

/// Solves `problem` with `solver` within `limits`, relaxing the minima if needed (see above).
/// Throws std::invalid_argument when a group's minimum exceeds its maximum, a relevance vector
/// is longer than camera_count, a relevance is infinite, or the threshold is negative or NaN.
csp_solution solve(const csp_problem& problem, csp_solver_kind solver,
                   const csp_limits& limits = {});

/// How `csp_stop` is spelled in output: "", "work", "time", "memory".
const char* stop_name(csp_stop stop) noexcept;

}  // namespace argus::protocol
