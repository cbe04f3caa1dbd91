#include "config/scenario_error.hpp"

#include <gtest/gtest.h>

namespace argus::config {
namespace {

TEST(scenario_error, formats_a_problem_like_a_compiler_diagnostic) {
  const problem located{"scenarios/x.yaml", 12, 5, "cameras[3].field_of_view_deg",
                        "expected a number in [5, 90] (within field_of_view_limits), got 200"};
  EXPECT_EQ(to_string(located),
            "scenarios/x.yaml:12:5: cameras[3].field_of_view_deg: expected a number in [5, 90] "
            "(within field_of_view_limits), got 200");
}

TEST(scenario_error, leaves_out_unknown_position_and_empty_field) {
  EXPECT_EQ(to_string(problem{"x.yaml", 0, 0, "", "cannot open file: No such file or directory"}),
            "x.yaml: cannot open file: No such file or directory");
  EXPECT_EQ(to_string(problem{"x.yaml", 3, 0, "run", "expected a mapping, got '5'"}),
            "x.yaml:3: run: expected a mapping, got '5'");
}

TEST(scenario_error, what_lists_every_problem_one_per_line) {
  const scenario_error error(
      {problem{"a.yaml", 1, 2, "run.tick", "first"}, problem{"a.yaml", 3, 4, "", "second"}});
  EXPECT_STREQ(error.what(), "a.yaml:1:2: run.tick: first\na.yaml:3:4: second");
  ASSERT_EQ(error.problems().size(), 2u);
  EXPECT_EQ(error.problems()[1].message, "second");
}

}  // namespace
}  // namespace argus::config
