#include "report/csv_table.hpp"

#include <gtest/gtest.h>

namespace argus::report {
namespace {

TEST(csv_table, columns_by_name_numbers_and_short_rows_dropped) {
  const auto table = csv_table::parse("tick,t,camera,state\r\n0,0.0,1,idle\n3,0.2,1\n5,x,2,down\n");
  ASSERT_TRUE(table.column("state"));
  EXPECT_EQ(*table.column("state"), 3u);
  EXPECT_FALSE(table.column("pan"));
  ASSERT_EQ(table.rows().size(), 2u);  // "3,0.2,1" is cut short: a run killed mid-line
  EXPECT_EQ(table.rows()[1][3], "down");
  EXPECT_DOUBLE_EQ(csv_table::number(table.rows()[0], 1), 0.0);
  EXPECT_DOUBLE_EQ(csv_table::number(table.rows()[1], 1, -7.0), -7.0);
}

TEST(csv_table, a_missing_file_reads_as_nothing) {
  EXPECT_FALSE(csv_table::read("/nonexistent/targets.csv"));
}

}  // namespace
}  // namespace argus::report
