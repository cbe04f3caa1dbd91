#include "report/confidence_interval.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace argus::report {
namespace {

TEST(confidence_interval, t_quantiles_from_the_table_and_between) {
  EXPECT_DOUBLE_EQ(t_quantile_975(1), 12.706);
  EXPECT_DOUBLE_EQ(t_quantile_975(9), 2.262);
  EXPECT_DOUBLE_EQ(t_quantile_975(30), 2.042);
  EXPECT_NEAR(t_quantile_975(40), 2.021, 1e-9);
  EXPECT_NEAR(t_quantile_975(50), 2.009, 0.002);  // tables: 2.009
  EXPECT_NEAR(t_quantile_975(1000000), 1.960, 1e-4);
}

TEST(confidence_interval, mean_and_half_width_of_a_known_sample) {
  // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, sample sd sqrt(32 / 7), t(0.975, 7) = 2.365.
  const std::vector<double> sample{2, 4, 4, 4, 5, 5, 7, 9};
  const auto m = mean_with_ci95(sample);
  EXPECT_EQ(m.count, 8u);
  EXPECT_DOUBLE_EQ(m.mean, 5.0);
  ASSERT_TRUE(m.half_width);
  EXPECT_NEAR(*m.half_width, 2.365 * std::sqrt(32.0 / 7.0) / std::sqrt(8.0), 1e-12);
}

TEST(confidence_interval, one_value_has_no_interval_and_none_has_no_mean) {
  const std::vector<double> one{0.5};
  EXPECT_FALSE(mean_with_ci95(one).half_width);
  EXPECT_DOUBLE_EQ(mean_with_ci95(one).mean, 0.5);
  EXPECT_EQ(mean_with_ci95({}).count, 0u);
}

}  // namespace
}  // namespace argus::report
