#include "config/ticks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string_view>

#include "config/duration.hpp"

namespace argus::config {
namespace {

// Durations as a scenario file writes them.
seconds parsed(std::string_view text) {
  const auto d = parse_duration(text);
  EXPECT_TRUE(d) << text;
  return d.value_or(seconds{-1.0});
}

struct expected_ticks {
  std::string_view duration;
  std::int64_t at_15_hz;
  std::int64_t at_30_hz;
};

TEST(ticks, to_ticks_rounds_to_the_nearest_tick_halves_up) {
  const seconds tick_15 = parsed("1/15 s"), tick_30 = parsed("1/30 s");
  for (const auto& [text, at_15, at_30] : {
           expected_ticks{"200 ms", 3, 6},
           expected_ticks{"500 ms", 8, 15},    // 7.5 ticks at 15 Hz: the half rounds up
           expected_ticks{"1500 ms", 23, 45},  // 22.5
           expected_ticks{"1 s", 15, 30},
           expected_ticks{"3 s", 45, 90},
           expected_ticks{"5 s", 75, 150},
           expected_ticks{"2 min", 1800, 3600},
           expected_ticks{"5 min", 4500, 9000},
           expected_ticks{"1 h", 54000, 108000},
       }) {
    EXPECT_EQ(to_ticks(parsed(text), tick_15), at_15) << text;
    EXPECT_EQ(to_ticks(parsed(text), tick_30), at_30) << text;
    // The same from literals written in code.
    EXPECT_EQ(to_ticks(parsed(text), seconds{1.0 / 15.0}), at_15) << text;
    EXPECT_EQ(to_ticks(parsed(text), seconds{1.0 / 30.0}), at_30) << text;
  }
}

TEST(ticks, edge_cases) {
  const seconds tick{1.0 / 15.0};
  EXPECT_EQ(to_ticks(seconds{0.0}, tick), 0);
  EXPECT_EQ(to_ticks(seconds{0.001}, tick), 0);
  EXPECT_EQ(to_ticks(seconds{1.0 / 30.0}, tick), 1);  // exactly half a tick rounds up
  EXPECT_EQ(to_ticks(0.49 * tick, tick), 0);
  EXPECT_EQ(to_ticks(0.51 * tick, tick), 1);
  // Binary error: 0.1 + 0.2 s is 0.30000000000000004 s.
  EXPECT_EQ(to_ticks(seconds{0.1 + 0.2}, seconds{0.1}), 3);
  // A quotient a hair under a half (floating error) still counts as the half...
  EXPECT_EQ(to_ticks(seconds{std::nextafter(22.5 * tick.count(), 0.0)}, tick), 23);
  // ... but a millionth of a tick under it does not.
  EXPECT_EQ(to_ticks((22.5 - 1e-6) * tick, tick), 22);
  // A day of ticks.
  EXPECT_EQ(to_ticks(seconds{86400.0}, tick), 1296000);
  EXPECT_EQ(to_ticks(seconds{86400.0}, seconds{1.0 / 30.0}), 2592000);
}

TEST(ticks, at_least_one) {
  const seconds tick{1.0 / 15.0};
  EXPECT_EQ(to_ticks_at_least_one(seconds{0.0}, tick), 1);
  EXPECT_EQ(to_ticks_at_least_one(seconds{0.001}, tick), 1);
  EXPECT_EQ(to_ticks_at_least_one(seconds{1.0}, tick), 15);
  EXPECT_EQ(to_ticks_at_least_one(parsed("1500 ms"), tick), 23);
}

TEST(ticks, covering_rounds_up_and_within_rounds_down) {
  const seconds tick_15{1.0 / 15.0}, tick_30{1.0 / 30.0};
  // On a boundary (up to binary error) both give the boundary.
  EXPECT_EQ(ticks_covering(parsed("200 ms"), tick_15), 3);
  EXPECT_EQ(ticks_within(parsed("200 ms"), tick_15), 3);
  EXPECT_EQ(ticks_covering(seconds{0.1 + 0.2}, seconds{0.1}), 3);
  EXPECT_EQ(ticks_within(seconds{0.3}, seconds{0.1}), 3);  // 2.9999999999999996
  EXPECT_EQ(ticks_covering(parsed("1 s"), tick_30), 30);
  EXPECT_EQ(ticks_within(parsed("1 s"), tick_30), 30);
  // Between boundaries they part.
  EXPECT_EQ(ticks_covering(parsed("500 ms"), tick_15), 8);
  EXPECT_EQ(ticks_within(parsed("500 ms"), tick_15), 7);
  EXPECT_EQ(ticks_covering(parsed("1500 ms"), tick_15), 23);
  EXPECT_EQ(ticks_within(parsed("1500 ms"), tick_15), 22);
  EXPECT_EQ(ticks_covering(parsed("210 ms"), tick_15), 4);
  EXPECT_EQ(ticks_within(parsed("210 ms"), tick_15), 3);
  EXPECT_EQ(ticks_covering(seconds{0.0}, tick_15), 0);
  EXPECT_EQ(ticks_within(seconds{0.0}, tick_15), 0);
}

TEST(ticks, to_seconds_inverts_to_ticks) {
  for (const seconds tick : {seconds{1.0 / 15.0}, seconds{1.0 / 30.0}, seconds{0.1}}) {
    for (std::int64_t n : {0, 1, 3, 7, 22, 23, 1800, 1296000}) {
      EXPECT_EQ(to_ticks(to_seconds(n, tick), tick), n);
      EXPECT_EQ(ticks_covering(to_seconds(n, tick), tick), n);
      EXPECT_EQ(ticks_within(to_seconds(n, tick), tick), n);
    }
  }
  EXPECT_DOUBLE_EQ(to_seconds(45, seconds{1.0 / 15.0}).count(), 3.0);
}

}  // namespace
}  // namespace argus::config
