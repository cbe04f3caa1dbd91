#include "config/duration.hpp"

#include <gtest/gtest.h>

namespace argus::config {
namespace {

TEST(parse_duration, reads_every_unit_with_and_without_a_space) {
  EXPECT_EQ(parse_duration("1500 ms"), seconds{1.5});
  EXPECT_EQ(parse_duration("1500ms"), seconds{1.5});
  EXPECT_EQ(parse_duration("1.5 s"), seconds{1.5});
  EXPECT_EQ(parse_duration("2 min"), seconds{120.0});
  EXPECT_EQ(parse_duration("1 h"), seconds{3600.0});
  EXPECT_EQ(parse_duration("0 s"), seconds{0.0});
  EXPECT_EQ(parse_duration("  3 s  "), seconds{3.0});
  EXPECT_EQ(parse_duration("1e-3 s"), seconds{0.001});
}

TEST(parse_duration, milliseconds_give_the_double_nearest_the_decimal) {
  // 200 * 0.001 would be 0.20000000000000001; the default min_delay is the literal 0.200.
  EXPECT_EQ(parse_duration("200 ms")->count(), 0.2);
  EXPECT_EQ(parse_duration("100 ms")->count(), 0.1);
}

TEST(parse_duration, reads_fractions) {
  EXPECT_EQ(parse_duration("1/15 s"), seconds{1.0 / 15.0});
  EXPECT_EQ(parse_duration("3/4 min"), seconds{45.0});
  EXPECT_EQ(parse_duration("-1/15 s"), seconds{-1.0 / 15.0});
}

TEST(parse_duration, rejects_bare_numbers_and_bad_units) {
  EXPECT_EQ(parse_duration("1500"), std::nullopt);
  EXPECT_EQ(parse_duration("0"), std::nullopt);
  EXPECT_EQ(parse_duration("1.5"), std::nullopt);
  EXPECT_EQ(parse_duration("1500 us"), std::nullopt);
  EXPECT_EQ(parse_duration("2 mins"), std::nullopt);
  EXPECT_EQ(parse_duration("2 S"), std::nullopt);
  EXPECT_EQ(parse_duration("s"), std::nullopt);
  EXPECT_EQ(parse_duration(""), std::nullopt);
  EXPECT_EQ(parse_duration("abc s"), std::nullopt);
  EXPECT_EQ(parse_duration("1 2 s"), std::nullopt);
  EXPECT_EQ(parse_duration("1/0 s"), std::nullopt);
  EXPECT_EQ(parse_duration("inf s"), std::nullopt);
  EXPECT_EQ(parse_duration("nan s"), std::nullopt);
}

TEST(format_duration, prefers_a_whole_number_of_the_largest_unit) {
  EXPECT_EQ(format_duration(seconds{0.0}), "0 s");
  EXPECT_EQ(format_duration(seconds{1.5}), "1500 ms");
  EXPECT_EQ(format_duration(seconds{0.2}), "200 ms");
  EXPECT_EQ(format_duration(seconds{1.0}), "1 s");
  EXPECT_EQ(format_duration(seconds{90.0}), "90 s");
  EXPECT_EQ(format_duration(seconds{120.0}), "2 min");
  EXPECT_EQ(format_duration(seconds{5400.0}), "90 min");
  EXPECT_EQ(format_duration(seconds{7200.0}), "2 h");
  EXPECT_EQ(format_duration(seconds{-2.0}), "-2 s");
}

TEST(format_duration, writes_one_over_n_seconds_as_a_fraction) {
  EXPECT_EQ(format_duration(seconds{1.0 / 15.0}), "1/15 s");
  EXPECT_EQ(format_duration(seconds{1.0 / 30.0}), "1/30 s");
  EXPECT_EQ(format_duration(seconds{-1.0 / 3.0}), "-1/3 s");
}

TEST(format_duration, falls_back_to_the_shortest_exact_decimal) {
  EXPECT_EQ(format_duration(seconds{0.0005}), "0.0005 s");
  EXPECT_EQ(format_duration(seconds{0.1 + 0.2}), "0.30000000000000004 s");
  EXPECT_EQ(format_duration(seconds{2.0 / 3.0}), "0.6666666666666666 s");
}

TEST(format_duration, round_trips_exactly) {
  for (const double value : {1.0 / 15.0, 1.0 / 7.0, 0.2, 0.1 + 0.2, 1.5, 2.0 / 3.0, 1e-7, 1234.5678,
                             59.999, 86400.0, 1e20, -0.25}) {
    const auto text = format_duration(seconds{value});
    const auto back = parse_duration(text);
    ASSERT_TRUE(back.has_value()) << text;
    EXPECT_EQ(back->count(), value) << text;
  }
}

}  // namespace
}  // namespace argus::config
