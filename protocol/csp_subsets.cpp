#include "protocol/csp_subsets.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace argus::protocol {

lexicographic_subsets::lexicographic_subsets(std::span<const std::size_t> cameras,
                                             unsigned min_size, unsigned max_size)
    : cameras_(cameras), min_size_(min_size), max_size_(max_size) {
  positions_.reserve(std::min<std::size_t>(max_size_, cameras_.size()));
}

bool heaviest_first_subsets::lighter::operator()(const candidate& a, const candidate& b) const {
  if (a.weight != b.weight) return a.weight < b.weight;
  if (a.positions.size() != b.positions.size()) return a.positions.size() > b.positions.size();
  return a.positions > b.positions;
}

heaviest_first_subsets::heaviest_first_subsets(std::vector<std::size_t> cameras,
                                               std::vector<double> weights, unsigned min_size,
                                               unsigned max_size)
    : cameras_(std::move(cameras)), weights_(std::move(weights)) {
  const std::size_t largest = std::min<std::size_t>(max_size, cameras_.size());
  entry_bytes_ = sizeof(candidate) + largest * sizeof(std::size_t);
  for (std::size_t size = min_size; size <= largest; ++size) {
    std::vector<std::size_t> first(size);
    std::iota(first.begin(), first.end(), std::size_t{0});
    push(std::move(first), size == 0 ? 0 : size - 1);
  }
}

void heaviest_first_subsets::push(std::vector<std::size_t> positions, std::size_t moving) {
  double weight = 0.0;
  for (std::size_t p : positions) weight += weights_[p];
  heap_.push(candidate{weight, std::move(positions), moving});
}

bool heaviest_first_subsets::next() {
  if (heap_.empty()) return false;
  candidate top = heap_.top();
  heap_.pop();
  const auto& p = top.positions;
  current_.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) current_[i] = cameras_[p[i]];
  weight_ = top.weight;
  if (p.empty()) return true;
  const std::size_t i = top.moving;
  // Child 1: the moving element one slot further right, if that slot is free.
  const std::size_t limit = i + 1 < p.size() ? p[i + 1] : cameras_.size();
  if (p[i] + 1 < limit) {
    auto child = p;
    ++child[i];
    push(std::move(child), i);
  }
  // Child 2: once the moving element has left its first slot, start moving the one before it.
  if (i > 0 && p[i - 1] + 1 < p[i]) {
    auto child = p;
    ++child[i - 1];
    push(std::move(child), i - 1);
  }
  return true;
}

}  // namespace argus::protocol
