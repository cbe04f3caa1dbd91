#pragma once

// Lazy enumeration of a CSP group's domain values (protocol/csp.hpp): the subsets of a list
// of cameras whose size lies in [min_size, max_size], one at a time, never materialised.

#include <cstddef>
#include <queue>
#include <span>
#include <vector>

namespace argus::protocol {

/// The subsets of `cameras` (ascending) of size min_size..max_size in lexicographic order of
/// their ascending camera lists ({} < {0} < {0,1} < {0,1,2} < {0,2} < {1} ...): a preorder walk
/// of the tree whose children extend a list by a later camera. The order AllSolv and BestSolv
/// assign values in, so the first of equally heavy complete assignments is the smallest.
class lexicographic_subsets {
 public:
  /// Enumerates subsets of `cameras`, which must outlive this object.
  lexicographic_subsets(std::span<const std::size_t> cameras, unsigned min_size, unsigned max_size);

  /// Moves to the next subset; false when there is none left.
  bool next();

  /// The current subset, ascending (valid after next() returned true).
  const std::vector<std::size_t>& current() const noexcept { return current_; }

 private:
  /// Moves to the next node of the preorder walk that can still reach min_size_; false at end.
  bool step();

  std::span<const std::size_t> cameras_;
  std::size_t min_size_;
  std::size_t max_size_;
  bool started_ = false;
  bool finished_ = false;
  std::vector<std::size_t> positions_;  // into cameras_, ascending
  std::vector<std::size_t> current_;
};

// Inline: AllSolv and BestSolv call next() once per value they try (inlining halved AllSolv's
// time on Table 1's instances).
inline bool lexicographic_subsets::step() {
  const std::size_t n = cameras_.size();
  if (!started_) {  // the root, the empty list
    started_ = true;
    return n >= min_size_;
  }
  // First child: extend by the next camera, if the extension can still reach min_size_.
  if (positions_.size() < max_size_) {
    const std::size_t next = positions_.empty() ? 0 : positions_.back() + 1;
    if (next < n && positions_.size() + (n - next) >= min_size_) {
      positions_.push_back(next);
      return true;
    }
  }
  // Else the next sibling of this node or of its nearest ancestor that has one.
  while (!positions_.empty()) {
    const std::size_t last = ++positions_.back();
    if (last < n && positions_.size() + (n - 1 - last) >= min_size_) return true;
    positions_.pop_back();
  }
  return false;
}

inline bool lexicographic_subsets::next() {
  while (!finished_) {
    if (!step()) {
      finished_ = true;
      break;
    }
    if (positions_.size() >= min_size_) {
      current_.resize(positions_.size());
      for (std::size_t i = 0; i < positions_.size(); ++i) current_[i] = cameras_[positions_[i]];
      return true;
    }
  }
  return false;
}

/// The subsets of `cameras` of size min_size..max_size in nonincreasing order of their weight
/// (the sum of `weights` over the subset), generated lazily with a heap. `cameras` must be
/// sorted by weight, heaviest first. Each subset of size s is a set of positions
/// p_1 < ... < p_s; the lightest-positioned set {0..s-1} is the heaviest. A subset's parent
/// undoes the last of the moves that took it there from {0..s-1}, moving the last element
/// first, then the one before it, and so on, each one slot right at a time; so every subset
/// has one parent, is no heavier than it, and each popped subset pushes at most two children.
class heaviest_first_subsets {
 public:
  /// Enumerates subsets of `cameras` with their `weights` (same length, nonincreasing).
  heaviest_first_subsets(std::vector<std::size_t> cameras, std::vector<double> weights,
                         unsigned min_size, unsigned max_size);

  /// Moves to the next subset; false when there is none left.
  bool next();

  /// The current subset's cameras, in the order of `cameras` (not sorted by index).
  const std::vector<std::size_t>& current() const noexcept { return current_; }

  /// The current subset's weight (summed in position order).
  double weight() const noexcept { return weight_; }

  /// About how many bytes the subsets waiting in the heap hold (for a search's memory budget).
  std::size_t held_bytes() const noexcept { return heap_.size() * entry_bytes_; }

 private:
  struct candidate {
    double weight;
    std::vector<std::size_t> positions;
    std::size_t moving;  // index in positions of the element moved last (see above)
  };
  struct lighter {
    bool operator()(const candidate& a, const candidate& b) const;
  };

  void push(std::vector<std::size_t> positions, std::size_t moving);

  std::vector<std::size_t> cameras_;
  std::vector<double> weights_;
  std::priority_queue<candidate, std::vector<candidate>, lighter> heap_;
  std::vector<std::size_t> current_;
  double weight_ = 0.0;
  std::size_t entry_bytes_ = 0;
};

}  // namespace argus::protocol
