// Dijkstra's open list for the distance fields (world/open_cells.hpp): every pop is a least
// distance still held, as a binary heap's would be, on the workloads a Dijkstra makes (pushes
// never below the last pop, ties, and stale entries pushed again).
#include "world/open_cells.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <vector>

namespace argus::world {
namespace {

using entry = std::pair<float, int>;
using reference = std::priority_queue<entry, std::vector<entry>, std::greater<>>;

// Pops both until empty, pushing `fan_out` successors of each pop at random steps.
void run_against_a_binary_heap(std::uint32_t seed, int starts, int fan_out, int limit) {
  std::mt19937 random(seed);
  // Steps from a few values, so that equal distances (ties) are common, as on a grid.
  const std::vector<float> steps{0.5f, 0.70710677f, 0.55f, 0.5f * 1.6f, 1e-3f};
  open_cells open;
  reference heap;
  int cell = 0;
  for (int s = 0; s < starts; ++s) {
    open.push(0.0f, cell);
    heap.push({0.0f, cell});
    ++cell;
  }
  int pops = 0;
  while (!heap.empty()) {
    ASSERT_FALSE(open.empty());
    const auto [d, c] = open.pop();
    const float least = heap.top().first;
    // Ties may come out in another order: the distance must be the least, and the cell one
    // that was pushed with it (the reference holds it).
    ASSERT_EQ(d, least) << "pop " << pops;
    std::vector<entry> popped;
    while (!heap.empty() && heap.top().first == least && heap.top().second != c) {
      popped.push_back(heap.top());
      heap.pop();
    }
    ASSERT_FALSE(heap.empty()) << "cell " << c << " was not held at " << d;
    heap.pop();
    for (const auto& e : popped) heap.push(e);
    ++pops;
    if (cell >= limit) continue;
    for (int k = 0; k < fan_out; ++k) {
      const float next = d + steps[random() % steps.size()];
      open.push(next, cell);
      heap.push({next, cell});
      ++cell;
    }
  }
  EXPECT_TRUE(open.empty());
  EXPECT_EQ(pops, cell);
}

TEST(open_cells, pops_what_a_binary_heap_pops_from_one_source) {
  run_against_a_binary_heap(1, 1, 3, 200000);
}

TEST(open_cells, pops_what_a_binary_heap_pops_from_many_sources) {
  run_against_a_binary_heap(2, 64, 2, 100000);
}

TEST(open_cells, zero_and_equal_distances_come_out_first) {
  open_cells open;
  open.push(0.0f, 7);
  open.push(0.0f, 8);
  EXPECT_EQ(open.pop().first, 0.0f);
  open.push(0.0f, 9);  // no lower than the last taken
  open.push(1.5f, 10);
  EXPECT_EQ(open.pop().first, 0.0f);
  EXPECT_EQ(open.pop().first, 0.0f);
  const auto last = open.pop();
  EXPECT_EQ(last.first, 1.5f);
  EXPECT_EQ(last.second, 10);
  EXPECT_TRUE(open.empty());
}

TEST(open_cells, distances_far_apart_keep_their_order) {
  // Keys whose bits differ in the exponent land in the high buckets, and are split again.
  open_cells open;
  const std::vector<float> pushed{1e-6f, 3.0f, 250.0f, 0.25f, 1e4f, 7.0f};
  for (std::size_t i = 0; i < pushed.size(); ++i) open.push(pushed[i], static_cast<int>(i));
  float previous = 0.0f;
  for (std::size_t i = 0; i < pushed.size(); ++i) {
    const float d = open.pop().first;
    EXPECT_GE(d, previous);
    previous = d;
  }
  EXPECT_EQ(previous, 1e4f);
}

}  // namespace
}  // namespace argus::world
