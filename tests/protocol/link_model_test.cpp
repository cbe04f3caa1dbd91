#include "protocol/link_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace argus::protocol {
namespace {

constexpr double tick = 1.0 / 15.0;

TEST(link_model, delays_stay_within_table_2_bounds_on_tick_boundaries) {
  config::network_settings net;  // 200-500 ms
  link_model model(net, tick);
  pcg64 rng(7);
  std::int64_t lo = 1000, hi = 0;
  double sum = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    auto f = model.draw(rng);
    lo = std::min(lo, f.delay_ticks);
    hi = std::max(hi, f.delay_ticks);
    sum += static_cast<double>(f.delay_ticks);
  }
  EXPECT_EQ(lo, 3);  // 200 ms = 3 ticks exactly
  EXPECT_EQ(hi, 7);  // 467 ms: 8 ticks would be 533 ms, past the 500 ms bound
  // Unbiased: the mean stays at 350 ms = 5.25 ticks (clamping 7.5 to 7 takes ~0.01 off).
  EXPECT_NEAR(sum / n, 5.24, 0.05);
}

TEST(link_model, loss_rate_matches_the_probability) {
  config::network_settings net;  // loss 0.1
  link_model model(net, tick);
  pcg64 rng(11);
  const int n = 50000;
  int lost = 0;
  for (int i = 0; i < n; ++i) lost += model.draw(rng).lost ? 1 : 0;
  double rate = static_cast<double>(lost) / n;
  // 5 standard deviations of a binomial(50000, 0.1) rate: 0.0067.
  EXPECT_NEAR(rate, 0.1, 5 * std::sqrt(0.1 * 0.9 / n));
  int burst_lost = 0;
  for (int i = 0; i < 1000; ++i) burst_lost += model.draw(rng, 1.0).lost ? 1 : 0;
  EXPECT_EQ(burst_lost, 1000);
}

TEST(link_model, duplicates_with_the_scenario_probability_and_repeats_per_seed) {
  config::network_settings net;
  net.duplicate_probability = 0.25;
  link_model model(net, tick);
  pcg64 a(3), b(3), c(4);
  int dup = 0, same_as_b = 0, same_as_c = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    auto fa = model.draw(a), fb = model.draw(b), fc = model.draw(c);
    dup += fa.duplicated ? 1 : 0;
    same_as_b += (fa.lost == fb.lost && fa.delay_ticks == fb.delay_ticks) ? 1 : 0;
    same_as_c += (fa.lost == fc.lost && fa.delay_ticks == fc.delay_ticks) ? 1 : 0;
  }
  EXPECT_NEAR(static_cast<double>(dup) / n, 0.25, 0.02);
  EXPECT_EQ(same_as_b, n);
  EXPECT_LT(same_as_c, n / 2);
}

}  // namespace
}  // namespace argus::protocol
