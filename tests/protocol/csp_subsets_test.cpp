#include "protocol/csp_subsets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace argus::protocol {
namespace {

using subset = std::vector<std::size_t>;

/// Every subset of `cameras` with size in [min_size, max_size], by bit mask, sorted by
/// std::vector's lexicographic order.
std::vector<subset> all_subsets(const subset& cameras, unsigned min_size, unsigned max_size) {
  std::vector<subset> out;
  for (unsigned mask = 0; mask < (1u << cameras.size()); ++mask) {
    subset s;
    for (std::size_t i = 0; i < cameras.size(); ++i)
      if (mask & (1u << i)) s.push_back(cameras[i]);
    if (s.size() >= min_size && s.size() <= max_size) out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<subset> lexicographic(const subset& cameras, unsigned min_size, unsigned max_size) {
  lexicographic_subsets values(cameras, min_size, max_size);
  std::vector<subset> out;
  while (values.next()) out.push_back(values.current());
  EXPECT_FALSE(values.next()) << "an exhausted enumeration stays exhausted";
  return out;
}

TEST(lexicographic_subsets, lists_sizes_in_range_in_lexicographic_order) {
  const subset cameras{2, 5, 7, 9};
  EXPECT_EQ(
      lexicographic(cameras, 1, 2),
      (std::vector<subset>{{2}, {2, 5}, {2, 7}, {2, 9}, {5}, {5, 7}, {5, 9}, {7}, {7, 9}, {9}}));
  EXPECT_EQ(lexicographic(cameras, 0, 1), (std::vector<subset>{{}, {2}, {5}, {7}, {9}}));
  EXPECT_EQ(lexicographic(cameras, 4, 6), (std::vector<subset>{{2, 5, 7, 9}}));
  EXPECT_TRUE(lexicographic(cameras, 5, 6).empty());
  EXPECT_EQ(lexicographic({}, 0, 3), (std::vector<subset>{{}}));
  EXPECT_TRUE(lexicographic({}, 1, 3).empty());
  EXPECT_EQ(lexicographic(cameras, 0, 0), (std::vector<subset>{{}}));
}

TEST(lexicographic_subsets, matches_every_size_range_of_a_bit_mask_enumeration) {
  const subset cameras{0, 1, 3, 4, 6, 8, 11};
  for (unsigned lo = 0; lo <= 8; ++lo)
    for (unsigned hi = lo; hi <= 8; ++hi)
      EXPECT_EQ(lexicographic(cameras, lo, hi), all_subsets(cameras, lo, hi))
          << "sizes " << lo << ".." << hi;
}

TEST(heaviest_first_subsets, lists_each_subset_once_heaviest_first) {
  const subset cameras{4, 1, 7, 0, 3, 9, 2};
  const std::vector<double> weights{0.9, 0.8, 0.8, 0.5, 0.3, 0.3, 0.1};
  for (unsigned lo = 0; lo <= 7; ++lo) {
    for (unsigned hi = lo; hi <= 8; ++hi) {
      heaviest_first_subsets values(cameras, weights, lo, hi);
      std::vector<subset> seen;
      double previous = 1e9;
      while (values.next()) {
        double weight = 0.0;
        for (std::size_t c : values.current())
          weight += weights[static_cast<std::size_t>(std::find(cameras.begin(), cameras.end(), c) -
                                                     cameras.begin())];
        EXPECT_NEAR(values.weight(), weight, 1e-12);
        EXPECT_LE(values.weight(), previous + 1e-12) << "sizes " << lo << ".." << hi;
        previous = values.weight();
        subset sorted = values.current();
        std::sort(sorted.begin(), sorted.end());
        seen.push_back(sorted);
      }
      std::sort(seen.begin(), seen.end());
      subset ascending = cameras;
      std::sort(ascending.begin(), ascending.end());
      EXPECT_EQ(seen, all_subsets(ascending, lo, hi)) << "sizes " << lo << ".." << hi;
    }
  }
}

TEST(heaviest_first_subsets, is_lazy_on_a_domain_too_large_to_list) {
  // C(60, 30) is about 1.2e17 subsets; the heaviest few come at once.
  subset cameras(60);
  std::vector<double> weights(60);
  for (std::size_t i = 0; i < 60; ++i) {
    cameras[i] = i;
    weights[i] = 1.0 - 0.01 * static_cast<double>(i);
  }
  heaviest_first_subsets values(cameras, weights, 30, 30);
  ASSERT_TRUE(values.next());
  EXPECT_EQ(values.current().size(), 30u);
  EXPECT_EQ(values.current().back(), 29u);
  ASSERT_TRUE(values.next());
  EXPECT_EQ(values.current().back(), 30u) << "the second heaviest swaps 29 for 30";
}

}  // namespace
}  // namespace argus::protocol
