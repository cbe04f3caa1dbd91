#include "config/value_bounds.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace argus::config {
namespace {

TEST(value_bounds, closed_and_open_ends_include_or_exclude_their_limit) {
  EXPECT_TRUE(value_bounds::closed(0, 1).contains(0));
  EXPECT_TRUE(value_bounds::closed(0, 1).contains(1));
  EXPECT_FALSE(value_bounds::closed(0, 1).contains(1.5));
  EXPECT_FALSE(value_bounds::open(0, 180).contains(0));
  EXPECT_FALSE(value_bounds::open(0, 180).contains(180));
  EXPECT_TRUE(value_bounds::left_open(0, 1).contains(1));
  EXPECT_FALSE(value_bounds::above(0).contains(0));
  EXPECT_TRUE(value_bounds::at_least(0).contains(0));
  EXPECT_FALSE(value_bounds::at_most(256).contains(257));
  EXPECT_TRUE(value_bounds::any().contains(-1e300));
  EXPECT_FALSE(value_bounds::any().contains(std::nan("")));
}

TEST(value_bounds, describes_itself_in_words) {
  EXPECT_EQ(value_bounds::closed(0, 1).describe(), "in [0, 1]");
  EXPECT_EQ(value_bounds::open(0, 180).describe(), "in (0, 180)");
  EXPECT_EQ(value_bounds::left_open(0, 1).describe(), "in (0, 1]");
  EXPECT_EQ(value_bounds::above(0).describe(), "> 0");
  EXPECT_EQ(value_bounds::at_least(1).describe(), ">= 1");
  EXPECT_EQ(value_bounds::at_most(256).describe(), "<= 256");
  EXPECT_EQ(value_bounds::closed(0, 1'000'000).describe(), "in [0, 1000000]");
  EXPECT_EQ(value_bounds::any().describe(), "");
  EXPECT_EQ(value_bounds::above(0).describe([](double) { return std::string{"zero"}; }), "> zero");
}

}  // namespace
}  // namespace argus::config
