// AllSolv, BestSolv and optimistic_solv (Section IV-B, Table 1): plain backtracking over the
// groups in index order, each group's domain in lexicographic order. BestSolv drops what is
// poorer than the best taken to the same depth (the paper's rule); optimistic_solv drops what
// cannot reach the best even with a static optimistic completion.

#include <algorithm>
#include <functional>

#include "protocol/csp_search.hpp"
#include "protocol/csp_subsets.hpp"

namespace argus::protocol::csp_search {
namespace {

class lexicographic_backtracking {
 public:
  lexicographic_backtracking(const round_problem& round, lexicographic_pruning pruning)
      : round_(round),
        pruning_(pruning),
        group_count_(round.problem.groups.size()),
        taken_(round.problem.camera_count, 0),
        chosen_(group_count_),
        completion_(group_count_ + 1, 0.0),
        partials_(group_count_, 0.0),
        best_partials_(group_count_, 0.0) {
    // optimistic_solv's completion: for each group, its max_cameras largest relevances.
    for (std::size_t g = group_count_; g-- > 0;) {
      std::vector<double> values;
      for (std::size_t c : round_.relevant[g]) values.push_back(round_.relevance(g, c));
      const std::size_t top =
          std::min<std::size_t>(values.size(), round_.problem.groups[g].max_cameras);
      std::partial_sort(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(top),
                        values.end(), std::greater<>());
      double sum = 0.0;
      for (std::size_t i = 0; i < top; ++i) sum += values[i];
      completion_[g] = completion_[g + 1] + sum;
    }
  }

  outcome run() {
    return search_from_root(round_, best_, result_, [&] { visit(0, 0.0); });
  }

 private:
  bool clashes(const std::vector<std::size_t>& cameras) const {
    return std::any_of(cameras.begin(), cameras.end(), [&](std::size_t c) { return taken_[c]; });
  }

  void mark(const std::vector<std::size_t>& cameras, char taken) {
    for (std::size_t c : cameras) taken_[c] = taken;
  }

  /// Whether a value that brings the partial weight of groups 0..group to `weight` is pruned.
  bool pruned(std::size_t group, double weight) const {
    switch (pruning_) {
      case lexicographic_pruning::none:
        return false;
      case lexicographic_pruning::paper:  // poorer than the best result at the same depth
        return best_.found() && weight < best_partials_[group] - prune_margin;
      case lexicographic_pruning::optimistic:
        return weight + completion_[group + 1] < best_.weight() - prune_margin;
    }
    return false;
  }

  void visit(std::size_t group, double partial) {
    const auto& spec = round_.problem.groups[group];
    lexicographic_subsets values(round_.relevant[group], round_.minima[group], spec.max_cameras);
    const bool last = group + 1 == group_count_;
    while (values.next()) {
      if (!round_.budget.spend()) break;
      ++result_.backtracks;  // every generated value is taken back (csp.hpp, "Counting")
      const auto& cameras = values.current();
      if (clashes(cameras)) continue;
      double weight = partial;
      for (std::size_t c : cameras) weight += round_.relevance(group, c);
      if (pruned(group, weight)) continue;
      ++result_.nodes_explored;
      partials_[group] = weight;
      if (last) {
        ++result_.solutions;
        if (best_.may_take(weight)) {  // skips the copy for the many clearly lighter ones
          chosen_[group] = cameras;
          if (best_.offer(round_, chosen_, weight)) best_partials_ = partials_;
        }
        continue;
      }
      chosen_[group] = cameras;
      mark(cameras, 1);
      visit(group + 1, weight);
      mark(cameras, 0);
    }
    chosen_[group].clear();
  }

  const round_problem& round_;
  const lexicographic_pruning pruning_;
  const std::size_t group_count_;
  std::vector<char> taken_;
  assignment chosen_;
  std::vector<double> completion_;     // completion_[g]: bound for groups g.. (optimistic_solv)
  std::vector<double> partials_;       // partials_[g]: weight of groups 0..g on the current path
  std::vector<double> best_partials_;  // the same along the best assignment (BestSolv)
  incumbent best_;
  outcome result_;
};

}  // namespace

outcome lexicographic_search(const round_problem& round, lexicographic_pruning pruning) {
  return lexicographic_backtracking(round, pruning).run();
}

}  // namespace argus::protocol::csp_search
