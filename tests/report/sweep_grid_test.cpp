#include "report/sweep_grid.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace argus::report {
namespace {

TEST(sweep_grid, values_split_at_commas_outside_brackets) {
  const auto p = parse_swept_parameter("network.adjacency=[[1,2],[2,3]],[[1,3]]");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->key, "network.adjacency");
  EXPECT_EQ(p->values, (std::vector<std::string>{"[[1,2],[2,3]]", "[[1,3]]"}));
  EXPECT_EQ(parse_swept_parameter("world.population=5")->values, (std::vector<std::string>{"5"}));
  EXPECT_FALSE(parse_swept_parameter("world.population=5,,6"));
  EXPECT_FALSE(parse_swept_parameter("world.population"));
  EXPECT_FALSE(parse_swept_parameter("world.population="));
}

TEST(sweep_grid, every_combination_for_every_seed_first_parameter_slowest) {
  const auto runs = plan_runs({{"network.loss_probability", {"0", "0.2"}},
                               {"controller.solver", {"best_solv", "all_solv"}}},
                              2);
  ASSERT_EQ(runs.size(), 8u);
  EXPECT_EQ(runs[0].id, "loss_probability=0__solver=best_solv__seed=1");
  EXPECT_EQ(runs[1].id, "loss_probability=0__solver=best_solv__seed=2");
  EXPECT_EQ(runs[2].id, "loss_probability=0__solver=all_solv__seed=1");
  EXPECT_EQ(runs[7].id, "loss_probability=0.2__solver=all_solv__seed=2");
  EXPECT_EQ(runs[7].values, (std::vector<std::string>{"0.2", "all_solv"}));
  EXPECT_EQ(runs[7].seed, 2u);
}

TEST(sweep_grid, ids_stay_apart_when_names_or_values_collide) {
  const auto runs = plan_runs({{"a.rate", {"1"}}, {"b.rate", {"[1, 2]", "[1,2]"}}}, 1);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].id, "a.rate=1__b.rate=_1__2___seed=1");
  EXPECT_EQ(runs[1].id, "a.rate=1__b.rate=_1_2___seed=1");
  const auto same = plan_runs({{"x", {"a b", "a_b"}}}, 1);
  EXPECT_EQ(same[0].id, "x=a_b__seed=1");
  EXPECT_EQ(same[1].id, "x=a_b__v2__seed=1");
}

TEST(sweep_grid, many_keys_make_a_folder_name_that_fits_and_stays_apart) {
  std::vector<swept_parameter> every_camera;
  for (int k = 0; k < 16; ++k)
    every_camera.push_back({"cameras." + std::to_string(k) + ".field_of_view_deg", {"40"}});
  every_camera.back().values = {"40", "45"};
  const auto runs = plan_runs(every_camera, 1);
  std::set<std::string> ids;
  for (const auto& r : runs) {
    EXPECT_LE(r.id.size(), 255u) << r.id;
    ids.insert(r.id);
  }
  EXPECT_EQ(ids.size(), runs.size());
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(plan_runs(every_camera, 1)[1].id, runs[1].id);  // a resumed sweep finds its runs
  EXPECT_EQ(runs[0].id.substr(0, 30), "cameras.0.field_of_view_deg=40");
}

TEST(sweep_grid, no_parameters_is_one_point) {
  const auto runs = plan_runs({}, 3);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[2].id, "seed=3");
}

}  // namespace
}  // namespace argus::report
