#pragma once

// The searches behind protocol::solve (protocol/csp.hpp), one relaxation round each. Internal
// to argus_protocol: callers use solve().

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "protocol/csp.hpp"

namespace argus::protocol::csp_search {

/// A camera list per group, ascending: an assignment, complete or partial.
using assignment = std::vector<std::vector<std::size_t>>;

/// Searches drop a value only when it falls short of the best weight by more than this, so
/// that rounding never drops an exact tie (csp.hpp, "The solvers").
inline constexpr double prune_margin = 1e-9;

/// What the searches of one solve() have spent against its limits (csp.hpp, "Budgets").
class search_budget {
 public:
  explicit search_budget(const csp_limits& limits)
      : limits_(limits), start_(std::chrono::steady_clock::now()) {}

  /// Counts one generated value; false once any budget has run out (then for good).
  bool spend() {
    if (stopped_ != csp_stop::none) return false;
    ++work_;
    if (limits_.max_work != 0 && work_ > limits_.max_work) stopped_ = csp_stop::work;
    if (limits_.max_seconds > 0.0 && work_ % 1024 == 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() >
            limits_.max_seconds)
      stopped_ = csp_stop::time;
    return stopped_ == csp_stop::none;
  }

  /// Counts `bytes` more held; false (and stopped) when that passes the memory budget.
  bool hold(std::size_t bytes) {
    held_ += bytes;
    if (limits_.max_memory_bytes != 0 && held_ > limits_.max_memory_bytes &&
        stopped_ == csp_stop::none)
      stopped_ = csp_stop::memory;
    return stopped_ == csp_stop::none;
  }

  /// Counts `bytes` released.
  void release(std::size_t bytes) noexcept { held_ -= bytes; }

  bool stopped() const noexcept { return stopped_ != csp_stop::none; }
  csp_stop reason() const noexcept { return stopped_; }

 private:
  csp_limits limits_;
  std::chrono::steady_clock::time_point start_;
  std::uint64_t work_ = 0;
  std::size_t held_ = 0;
  csp_stop stopped_ = csp_stop::none;
};

/// The problem as the searches see it: the minima in force this round, and each group's
/// relevant cameras ascending.
struct round_problem {
  const csp_problem& problem;
  const std::vector<unsigned>& minima;
  const std::vector<std::vector<std::size_t>>& relevant;
  search_budget& budget;

  double relevance(std::size_t group, std::size_t camera) const {
    return problem.groups[group].relevance[camera];
  }
};

/// The cameras of each group with relevance >= threshold (NaN never), ascending.
std::vector<std::vector<std::size_t>> relevant_cameras(const csp_problem& problem);

/// The weight of a complete assignment, summed in the canonical order (groups in index order,
/// cameras ascending): the one double every solver compares.
double canonical_weight(const round_problem& round, const assignment& chosen);

/// The best complete assignment so far, with the leaf rule every solver shares: heavier wins,
/// an equal weight goes to the lexicographically smaller assignment.
class incumbent {
 public:
  /// Offers a complete assignment; `estimate` is its weight summed in any order, used only to
  /// skip the canonical sum for assignments that are clearly lighter. True when it became the
  /// best.
  bool offer(const round_problem& round, const assignment& chosen, double estimate);

  /// Whether a complete assignment whose weight, summed in any order, is `estimate` could
  /// replace the best (offer ignores those that cannot).
  bool may_take(double estimate) const noexcept {
    return !found_ || estimate >= weight_ - prune_margin;
  }

  /// The best weight so far, or -infinity before the first complete assignment.
  double weight() const noexcept { return weight_; }

  /// Whether any complete assignment was offered.
  bool found() const noexcept { return found_; }

  /// The best assignment (valid when found()).
  const assignment& best() const noexcept { return best_; }

 private:
  bool found_ = false;
  double weight_ = -std::numeric_limits<double>::infinity();
  assignment best_;
};

/// What one round's search found, and its effort (csp.hpp, "Counting").
struct outcome {
  bool found = false;
  assignment best;
  double weight = 0.0;
  std::uint64_t nodes_explored = 0;
  std::uint64_t backtracks = 0;
  std::uint64_t solutions = 0;
};

/// The frame every search shares: counts the root as a node; a problem without groups has
/// one complete assignment, the empty one, else `descend()` searches; the answer is what
/// `best` holds at the end, with the effort `descend` counted in `effort`.
template <class Descend>
outcome search_from_root(const round_problem& round, incumbent& best, outcome& effort,
                         Descend descend) {
  ++effort.nodes_explored;
  if (round.problem.groups.empty()) {
    ++effort.solutions;
    best.offer(round, assignment{}, 0.0);
  } else {
    descend();
  }
  effort.found = best.found();
  if (effort.found) {
    effort.best = best.best();
    effort.weight = best.weight();
  }
  return effort;
}

/// How a lexicographic search prunes (csp.hpp, "The solvers").
enum class lexicographic_pruning {
  none,        // all_solv
  paper,       // best_solv: poorer than the best taken to the same depth
  optimistic,  // optimistic_solv: weight plus a static optimistic completion
};

/// AllSolv, BestSolv and optimistic_solv: groups in index order, values in lexicographic order.
outcome lexicographic_search(const round_problem& round, lexicographic_pruning pruning);

/// bound_solv: dynamic bound, forward checking, heaviest values first, most constrained
/// group first.
outcome bound_search(const round_problem& round);

}  // namespace argus::protocol::csp_search
