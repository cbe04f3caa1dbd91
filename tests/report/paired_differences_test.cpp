#include "report/paired_differences.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace argus::report {
namespace {

TEST(sign_test, exact_two_sided_binomial_probabilities) {
  EXPECT_DOUBLE_EQ(sign_test_p(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(sign_test_p(5, 0), 2.0 / 32.0);
  EXPECT_DOUBLE_EQ(sign_test_p(0, 5), 2.0 / 32.0);
  // n = 10, 8 to 2: 2 * (1 + 10 + 45) / 1024.
  EXPECT_NEAR(sign_test_p(8, 2), 112.0 / 1024.0, 1e-12);
  // An even split is no evidence either way (the doubled tail passes 1).
  EXPECT_DOUBLE_EQ(sign_test_p(3, 3), 1.0);
  // Many seeds: no factorial overflows; 2 * 0.5^1000 underflows to 0, not to NaN.
  EXPECT_NEAR(sign_test_p(500, 500), 1.0, 1e-12);
  EXPECT_GE(sign_test_p(1000, 0), 0.0);
  EXPECT_LT(sign_test_p(1000, 0), 1e-300);
  EXPECT_NEAR(sign_test_p(60, 40), 0.0569, 1e-4);  // a binomial table's 0.05689
}

// Parameter a (the compared one) at a0 (baseline), a1, a2; parameter b at b0, b1; seeds 1, 2.
// The runs at b1 are 10 higher than at b0 whatever a is, so a comparison that paired a run with
// the baseline run of another b would be 10 off.
sweep_results grid() {
  sweep_results r;
  r.parameters = {{"a", {"a0", "a1", "a2"}}, {"b", {"b0", "b1"}}};
  r.seeds = 2;
  auto run = [](std::string a, std::string b, std::uint64_t seed, nlohmann::json metric) {
    return sweep_run{a + b + std::to_string(seed), {a, b}, seed, 0, 1.0,
                     nlohmann::json{{"m", metric}}};
  };
  r.runs = {run("a0", "b0", 1, 1.0),  run("a0", "b0", 2, 2.0),  run("a0", "b1", 1, 11.0),
            run("a0", "b1", 2, 12.0), run("a1", "b0", 1, 1.5),  run("a1", "b0", 2, 2.0),
            run("a1", "b1", 1, 12.0), run("a1", "b1", 2, 11.9), run("a2", "b0", 1, nullptr),
            run("a2", "b0", 2, 2.5),  run("a2", "b1", 2, 11.0)};
  return r;
}

TEST(paired_differences, pairs_runs_of_the_same_seed_and_other_values_only) {
  const auto d = paired_differences(grid(), "m", 0);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].value, "a1");
  EXPECT_EQ(d[0].baseline, "a0");
  // a1 - a0: +0.5, 0, +1.0, -0.1.
  EXPECT_EQ(d[0].difference.count, 4u);
  EXPECT_NEAR(d[0].difference.mean, 0.35, 1e-12);
  const double sd = std::sqrt((0.15 * 0.15 + 0.35 * 0.35 + 0.65 * 0.65 + 0.45 * 0.45) / 3.0);
  ASSERT_TRUE(d[0].difference.standard_error);
  EXPECT_NEAR(*d[0].difference.standard_error, sd / 2.0, 1e-12);
  ASSERT_TRUE(d[0].difference.half_width);
  EXPECT_NEAR(*d[0].difference.half_width, 3.182 * sd / 2.0, 1e-9);  // t(0.975, 3)
  EXPECT_EQ(d[0].higher, 2u);
  EXPECT_EQ(d[0].lower, 1u);
  EXPECT_EQ(d[0].equal, 1u);
  EXPECT_NEAR(d[0].sign_test_p, sign_test_p(2, 1), 1e-12);
  // a2 - a0: seed 1 at b0 has no metric and a2 at b1 seed 1 never ran: +0.5 and -1.0 remain.
  EXPECT_EQ(d[1].difference.count, 2u);
  EXPECT_NEAR(d[1].difference.mean, -0.25, 1e-12);
  EXPECT_EQ(d[1].higher, 1u);
  EXPECT_EQ(d[1].lower, 1u);
}

TEST(paired_differences, the_other_parameter_is_compared_within_each_value_of_the_first) {
  const auto d = paired_differences(grid(), "m", 1);
  ASSERT_EQ(d.size(), 1u);
  // b1 - b0 within a0 (+10, +10), a1 (+10.5, +9.9) and a2 (seed 2: +8.5).
  EXPECT_EQ(d[0].difference.count, 5u);
  EXPECT_NEAR(d[0].difference.mean, (10.0 + 10.0 + 10.5 + 9.9 + 8.5) / 5.0, 1e-12);
  EXPECT_EQ(d[0].higher, 5u);
}

TEST(paired_differences, differences_within_the_tolerance_count_as_equal) {
  auto r = grid();
  r.equal_within = 0.2;
  const auto d = paired_differences(r, "m", 0);
  EXPECT_EQ(d[0].higher, 2u);  // +0.5, +1.0
  EXPECT_EQ(d[0].lower, 0u);   // -0.1 is within 0.2
  EXPECT_EQ(d[0].equal, 2u);
  EXPECT_NEAR(d[0].difference.mean, 0.35, 1e-12);  // the mean takes every pair
  EXPECT_DOUBLE_EQ(d[0].sign_test_p, sign_test_p(2, 0));
}

TEST(paired_differences, none_for_a_single_value_or_a_metric_no_run_has) {
  auto r = grid();
  r.parameters[1].values = {"b0"};
  EXPECT_TRUE(paired_differences(r, "m", 1).empty());
  const auto d = paired_differences(grid(), "missing", 0);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].difference.count, 0u);
  EXPECT_FALSE(d[0].difference.half_width);
  EXPECT_DOUBLE_EQ(d[0].sign_test_p, 1.0);
}

}  // namespace
}  // namespace argus::report
