// bound_solv: branch and bound beyond the paper's BestSolv (protocol/csp.hpp, "The solvers"):
// a dynamic bound over the free cameras, forward checking, heaviest values first and the most
// constrained group first. Same answer as AllSolv, far fewer nodes.

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>

#include "protocol/csp_search.hpp"
#include "protocol/csp_subsets.hpp"

namespace argus::protocol::csp_search {
namespace {

class branch_and_bound {
 public:
  explicit branch_and_bound(const round_problem& round)
      : round_(round),
        group_count_(round.problem.groups.size()),
        taken_(round.problem.camera_count, 0),
        assigned_(group_count_, 0),
        chosen_(group_count_),
        by_relevance_(round.relevant),
        camera_best_(round.problem.camera_count, -1.0) {
    // Each group's relevant cameras heaviest first (ties by index), for the bound and values.
    for (std::size_t g = 0; g < group_count_; ++g)
      std::stable_sort(by_relevance_[g].begin(), by_relevance_[g].end(),
                       [&](std::size_t a, std::size_t b) {
                         return round_.relevance(g, a) > round_.relevance(g, b);
                       });
  }

  outcome run() {
    return search_from_root(round_, best_, result_, [&] {
      if (minima_reachable()) visit(0, 0.0);
    });
  }

 private:
  std::size_t free_relevant(std::size_t group) const {
    return static_cast<std::size_t>(std::count_if(by_relevance_[group].begin(),
                                                  by_relevance_[group].end(),
                                                  [&](std::size_t c) { return !taken_[c]; }));
  }

  /// Forward checking: every unassigned group still has enough free relevant cameras.
  bool minima_reachable() const {
    for (std::size_t g = 0; g < group_count_; ++g)
      if (!assigned_[g] && free_relevant(g) < round_.minima[g]) return false;
    return true;
  }

  /// The number of values an unassigned group still has: sum over its sizes of C(free, s).
  double value_count(std::size_t group) const {
    const std::size_t free = free_relevant(group);
    const std::size_t largest =
        std::min<std::size_t>(free, round_.problem.groups[group].max_cameras);
    double count = 0.0;
    double binomial = 1.0;  // C(free, s)
    for (std::size_t s = 0; s <= largest; ++s) {
      if (s >= round_.minima[group]) count += binomial;
      binomial = binomial * static_cast<double>(free - s) / static_cast<double>(s + 1);
    }
    return count;
  }

  /// Most constrained first: the unassigned group with the fewest values, ties by index.
  std::size_t next_group() const {
    std::size_t chosen = group_count_;
    double fewest = std::numeric_limits<double>::infinity();
    for (std::size_t g = 0; g < group_count_; ++g) {
      if (assigned_[g]) continue;
      const double count = value_count(g);
      if (count < fewest) {
        fewest = count;
        chosen = g;
      }
    }
    return chosen;
  }

  /// Upper bound on what the unassigned groups can add on the free cameras (csp.hpp): the
  /// smaller of the per-group bound and the per-camera bound.
  double completion_bound() {
    double per_group = 0.0;
    std::size_t capacity = 0;
    touched_.clear();
    for (std::size_t g = 0; g < group_count_; ++g) {
      if (assigned_[g]) continue;
      const unsigned max_cameras = round_.problem.groups[g].max_cameras;
      capacity += max_cameras;
      std::size_t counted = 0;
      for (std::size_t c : by_relevance_[g]) {
        if (taken_[c]) continue;
        const double r = round_.relevance(g, c);
        if (counted < max_cameras) {
          per_group += r;
          ++counted;
        }
        if (camera_best_[c] < 0.0) touched_.push_back(c);
        camera_best_[c] = std::max(camera_best_[c], r);
      }
    }
    std::vector<double> best_per_camera;
    best_per_camera.reserve(touched_.size());
    for (std::size_t c : touched_) {
      best_per_camera.push_back(camera_best_[c]);
      camera_best_[c] = -1.0;
    }
    const std::size_t top = std::min(capacity, best_per_camera.size());
    std::partial_sort(best_per_camera.begin(),
                      best_per_camera.begin() + static_cast<std::ptrdiff_t>(top),
                      best_per_camera.end(), std::greater<>());
    double per_camera = 0.0;
    for (std::size_t i = 0; i < top; ++i) per_camera += best_per_camera[i];
    return std::min(per_group, per_camera);
  }

  void mark(const std::vector<std::size_t>& cameras, char taken) {
    for (std::size_t c : cameras) taken_[c] = taken;
  }

  /// A generated value waiting its turn (see visit).
  struct pending_value {
    double total;   // its weight plus the completion bound: nothing below it is heavier
    double weight;  // the partial weight with it
    std::vector<std::size_t> cameras;
    std::uint64_t order;  // generation order, for ties
  };
  struct less_promising {
    bool operator()(const pending_value& a, const pending_value& b) const {
      return a.total != b.total ? a.total < b.total : a.order > b.order;
    }
  };

  /// Assigns the most constrained group, trying its values in nonincreasing order of their
  /// total (weight + completion bound). Values come lazily heaviest first; one is generated
  /// only while it could still have the largest total (its weight plus the bound before the
  /// value, `loose`, reaches the best pending total), and generation stops for good at the
  /// first whose weight plus `loose` cannot reach the best complete weight.
  void visit(std::size_t depth, double partial) {
    const std::size_t group = next_group();
    std::vector<std::size_t> free;
    std::vector<double> weights;
    for (std::size_t c : by_relevance_[group]) {
      if (taken_[c]) continue;
      free.push_back(c);
      weights.push_back(round_.relevance(group, c));
    }
    heaviest_first_subsets values(std::move(free), std::move(weights), round_.minima[group],
                                  round_.problem.groups[group].max_cameras);
    assigned_[group] = 1;
    // Taking more cameras never raises the bound, so this one holds for every value.
    const double loose = completion_bound();
    const bool last = depth + 1 == group_count_;
    std::priority_queue<pending_value, std::vector<pending_value>, less_promising> pending;
    std::size_t held = 0;  // bytes of `values` and `pending` counted in the budget
    const auto account = [&] {
      std::size_t now = values.held_bytes();
      // Reads the queue's entries through its container size only: each holds its cameras.
      now += pending.size() * (sizeof(pending_value) +
                               round_.problem.groups[group].max_cameras * sizeof(std::size_t));
      if (now > held)
        round_.budget.hold(now - held);
      else
        round_.budget.release(held - now);
      held = now;
    };
    std::uint64_t generated = 0;
    bool more = values.next();
    while (!round_.budget.stopped()) {
      while (more && pending.size() < max_pending &&
             (pending.empty() || partial + values.weight() + loose >= pending.top().total)) {
        if (!round_.budget.spend()) break;
        ++result_.backtracks;  // every generated value is taken back (csp.hpp, "Counting")
        const double weight = partial + values.weight();
        if (weight + loose < best_.weight() - prune_margin) {
          more = false;  // the rest are no heavier
          break;
        }
        mark(values.current(), 1);
        if (minima_reachable()) {
          const double total = weight + completion_bound();
          if (total >= best_.weight() - prune_margin)
            pending.push({total, weight, values.current(), generated++});
        }
        mark(values.current(), 0);
        more = values.next();
      }
      account();
      if (round_.budget.stopped()) break;
      if (pending.empty()) break;  // nothing generated: no value left, or the rest are hopeless
      if (pending.top().total < best_.weight() - prune_margin) {
        // Every value not yet tried, generated or not, has a total no larger than the top's
        // (the values come heaviest first), unless the queue filled up before the next value
        // fell below the top: then only the waiting ones are hopeless.
        if (!more || pending.size() < max_pending) break;
        pending = {};
        continue;
      }
      const pending_value value = pending.top();
      pending.pop();
      ++result_.nodes_explored;
      mark(value.cameras, 1);
      chosen_[group] = value.cameras;
      std::sort(chosen_[group].begin(), chosen_[group].end());
      if (last) {
        ++result_.solutions;
        best_.offer(round_, chosen_, value.weight);
      } else {
        visit(depth + 1, value.weight);
      }
      chosen_[group].clear();
      mark(value.cameras, 0);
    }
    round_.budget.release(held);
    assigned_[group] = 0;
  }

  /// Generated values waiting per group before one is searched (csp.hpp, "Budgets").
  static constexpr std::size_t max_pending = 4096;

  const round_problem& round_;
  const std::size_t group_count_;
  std::vector<char> taken_;
  std::vector<char> assigned_;
  assignment chosen_;
  std::vector<std::vector<std::size_t>> by_relevance_;
  std::vector<double> camera_best_;  // scratch for completion_bound, -1 between calls
  std::vector<std::size_t> touched_;
  incumbent best_;
  outcome result_;
};

}  // namespace

outcome bound_search(const round_problem& round) {
  return branch_and_bound(round).run();
}

}  // namespace argus::protocol::csp_search
