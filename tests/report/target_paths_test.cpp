#include "report/target_paths.hpp"

#include <gtest/gtest.h>

namespace argus::report {
namespace {

const std::filesystem::path data_dir{ARGUS_REPORT_TEST_DATA_DIR};

TEST(target_paths, each_task_in_time_order_with_its_observer) {
  const auto paths = target_paths_from(
      csv_table::parse("tick,t,task,pedestrian,x,y,present,reachable,observed_by\n"
                       "15,1.0,0,12,5,6,1,1,7\n"
                       "0,0.0,0,12,4,6,1,1,-1\n"
                       "0,0.0,3,2,9,9,0,0,-1\n"));
  ASSERT_EQ(paths.size(), 2u);
  const auto& zero = paths.at(0);
  ASSERT_EQ(zero.size(), 2u);
  EXPECT_DOUBLE_EQ(zero[0].x_m, 4.0);
  EXPECT_EQ(zero[0].observed_by, -1);
  EXPECT_EQ(zero[1].observed_by, 7);
  EXPECT_FALSE(paths.at(3)[0].present);
}

TEST(target_paths, the_fixture_run_has_two_tasks) {
  const auto table = csv_table::read(data_dir / "run" / "targets.csv");
  ASSERT_TRUE(table);
  const auto paths = target_paths_from(*table);
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(paths.at(1).front().observed_by, 9);
}

TEST(target_paths, a_file_without_the_columns_gives_no_paths) {
  EXPECT_TRUE(target_paths_from(csv_table::parse("a,b\n1,2\n")).empty());
}

}  // namespace
}  // namespace argus::report
