#include "config/edit_distance.hpp"

#include <gtest/gtest.h>

#include <array>

namespace argus::config {
namespace {

TEST(edit_distance, counts_insertions_deletions_substitutions_and_swaps) {
  EXPECT_EQ(edit_distance("speed", "speed"), 0u);
  EXPECT_EQ(edit_distance("speeed", "speed"), 1u);  // insertion
  EXPECT_EQ(edit_distance("sped", "speed"), 1u);    // deletion
  EXPECT_EQ(edit_distance("spead", "speed"), 1u);   // substitution
  EXPECT_EQ(edit_distance("sede", "seed"), 1u);     // adjacent swap
  EXPECT_EQ(edit_distance("", "tick"), 4u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(closest_match, suggests_the_nearest_key_within_two_edits) {
  constexpr std::array<std::string_view, 6> keys{"seed",  "duration", "tick",
                                                 "speed", "threads",  "output_dir"};
  EXPECT_EQ(closest_match("speeed", keys), "speed");
  EXPECT_EQ(closest_match("thread", keys), "threads");
  EXPECT_EQ(closest_match("outptu_dir", keys), "output_dir");
  EXPECT_EQ(closest_match("colour", keys), std::nullopt);
  EXPECT_EQ(closest_match("durashun", keys), std::nullopt);  // three edits away
}

TEST(closest_match, prefers_the_first_candidate_on_a_tie) {
  constexpr std::array<std::string_view, 2> keys{"ab", "ba"};
  EXPECT_EQ(closest_match("aa", keys), "ab");
}

}  // namespace
}  // namespace argus::config
