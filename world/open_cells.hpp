#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace argus::world {

/// Dijkstra's open list (station's distance fields): cells by distance, for distances that
/// never fall below the last one taken (a radix heap, Ahuja et al. 1990, on the bits of
/// non-negative floats, which order as their values do). A push is an append; a pop that finds
/// bucket 0 empty moves only the lowest non-empty bucket down. Which of two equally distant
/// cells comes out first does not matter: a cell's distance is the least over its neighbours of
/// theirs plus the step, whatever order they were settled in.
class open_cells {
 public:
  bool empty() const noexcept { return size_ == 0; }

  void push(float distance, int cell) {
    const auto key = std::bit_cast<std::uint32_t>(distance);
    buckets_[bucket_of(key)].push_back({key, cell});
    ++size_;
  }

  /// A cell of least distance, and that distance; the list must not be empty.
  std::pair<float, int> pop() {
    if (buckets_[0].empty()) {
      std::size_t b = 1;
      while (buckets_[b].empty()) ++b;
      auto& from = buckets_[b];
      last_ = std::min_element(from.begin(), from.end())->first;
      // Everything in the bucket now lies nearer the new least key: each goes to a lower one.
      for (const auto& e : from) buckets_[bucket_of(e.first)].push_back(e);
      from.clear();
    }
    const auto [key, cell] = buckets_[0].back();
    buckets_[0].pop_back();
    --size_;
    return {std::bit_cast<float>(key), cell};
  }

 private:
  // Bucket 0 holds keys equal to the last taken; bucket b, those whose highest bit that
  // differs from it is bit b - 1.
  std::size_t bucket_of(std::uint32_t key) const {
    return key == last_ ? 0 : 32 - static_cast<std::size_t>(std::countl_zero(key ^ last_));
  }

  std::array<std::vector<std::pair<std::uint32_t, int>>, 33> buckets_;
  std::uint32_t last_ = 0;
  std::size_t size_ = 0;
};

}  // namespace argus::world
