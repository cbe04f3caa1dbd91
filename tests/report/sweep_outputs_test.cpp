#include "report/sweep_outputs.hpp"

#include <gtest/gtest.h>

namespace argus::report {
namespace {

// Two values of one parameter, two seeds each; one run failed without metrics, one was never
// run (an interrupted sweep), one value reported null.
sweep_results example() {
  sweep_results r;
  r.scenario = "s.yaml";
  r.seeds = 2;
  r.parameters = {{"network.loss_probability", {"0", "0.2"}}, {"tasks.0.note", {"a,b"}}};
  auto summary = [](double coverage) {
    return nlohmann::json{{"mean_coverage", coverage}, {"handoffs", 3}, {"ratio", nullptr}};
  };
  r.runs = {{"l=0__seed=1", {"0", "a,b"}, 1, 0, 1.5, summary(0.9)},
            {"l=0__seed=2", {"0", "a,b"}, 2, 0, 1.25, summary(0.8)},
            {"l=0.2__seed=1", {"0.2", "a,b"}, 1, 1, 0.5, nullptr},
            {"l=0.2__seed=2", {"0.2", "a,b"}, 2, std::nullopt, 0.0, nullptr}};
  return r;
}

TEST(sweep_outputs, csv_has_a_row_per_run_and_a_column_per_metric) {
  EXPECT_EQ(sweep_csv(example()),
            "run,network.loss_probability,tasks.0.note,seed,exit_status,wall_s,handoffs,"
            "mean_coverage,ratio\n"
            "l=0__seed=1,0,\"a,b\",1,0,1.500,3,0.9,\n"
            "l=0__seed=2,0,\"a,b\",2,0,1.250,3,0.8,\n"
            "l=0.2__seed=1,0.2,\"a,b\",1,1,0.500,,,\n"
            "l=0.2__seed=2,0.2,\"a,b\",2,,,,,\n");
}

TEST(sweep_outputs, statistics_per_value) {
  const auto j = sweep_json(example());
  const auto& rows = j["statistics"]["mean_coverage"]["network.loss_probability"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["n"], 2);
  EXPECT_NEAR(rows[0]["mean"].get<double>(), 0.85, 1e-12);
  // sd = 0.0707, t(0.975, 1) = 12.706: half width 12.706 * 0.0707 / sqrt(2) = 0.6353.
  EXPECT_NEAR(rows[0]["ci95_high"].get<double>(), 0.85 + 0.6353, 1e-4);
  EXPECT_EQ(rows[1]["n"], 0);
  EXPECT_TRUE(rows[1]["mean"].is_null());
  EXPECT_TRUE(j["runs"][3]["exit_status"].is_null());
}

TEST(sweep_outputs, writes_plots_only_for_parameters_that_vary_and_metrics_with_values) {
  const auto dir = std::filesystem::path(testing::TempDir()) / "sweep_outputs_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto written = write_sweep_outputs(dir, example());
  EXPECT_TRUE(std::filesystem::exists(dir / "sweep.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "sweep.json"));
  EXPECT_TRUE(
      std::filesystem::exists(dir / "plots" / "mean_coverage_vs_network.loss_probability.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "plots" / "handoffs_vs_network.loss_probability.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "plots" / "ratio_vs_network.loss_probability.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "plots" / "mean_coverage_vs_tasks.0.note.png"));
  // No run at 0.2 has metrics, so nothing pairs and no paired plot is drawn.
  EXPECT_TRUE(std::filesystem::exists(dir / "paired.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "plots" /
                                       "mean_coverage_vs_network.loss_probability_paired.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "sweep.html"));
  EXPECT_EQ(written.size(), 6u);
}

// Two seeds at each of two values, both complete: the paired outputs.
sweep_results paired_example() {
  sweep_results r;
  r.scenario = "s.yaml";
  r.seeds = 2;
  r.parameters = {{"controller.strategy", {"paper", "oracle"}}};
  auto summary = [](double coverage) { return nlohmann::json{{"mean_coverage", coverage}}; };
  r.runs = {{"paper__seed=1", {"paper"}, 1, 0, 1.0, summary(0.25)},
            {"paper__seed=2", {"paper"}, 2, 0, 1.0, summary(0.5)},
            {"oracle__seed=1", {"oracle"}, 1, 0, 1.0, summary(0.75)},
            {"oracle__seed=2", {"oracle"}, 2, 0, 1.0, summary(0.5)}};
  return r;
}

TEST(sweep_outputs, paired_csv_and_json_compare_each_value_with_the_first_by_seed) {
  // oracle - paper: +0.5 and 0: mean 0.25, sd 0.353553, SE 0.25, t(0.975, 1) = 12.706.
  EXPECT_EQ(paired_csv(paired_example()),
            "metric,parameter,value,baseline,pairs,mean_difference,standard_error,ci95_low,"
            "ci95_high,higher,lower,equal,equal_within,sign_test_p\n"
            "mean_coverage,controller.strategy,oracle,paper,2,0.25,0.25,-2.9265,3.4265,1,0,1,0,"
            "1\n");
  const auto j = sweep_json(paired_example());
  const auto& row = j["paired"]["mean_coverage"]["controller.strategy"];
  ASSERT_EQ(row.size(), 1u);
  EXPECT_EQ(row[0]["value"], "oracle");
  EXPECT_EQ(row[0]["baseline"], "paper");
  EXPECT_EQ(row[0]["pairs"], 2);
  EXPECT_NEAR(row[0]["mean_difference"].get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(row[0]["ci95_high"].get<double>(), 3.4265, 1e-12);
  EXPECT_EQ(row[0]["higher"], 1);
  EXPECT_EQ(row[0]["equal"], 1);
  EXPECT_DOUBLE_EQ(row[0]["sign_test_p"].get<double>(), 1.0);
}

TEST(sweep_outputs, draws_the_paired_plot_where_runs_pair) {
  const auto dir = std::filesystem::path(testing::TempDir()) / "sweep_outputs_paired_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  write_sweep_outputs(dir, paired_example());
  EXPECT_TRUE(
      std::filesystem::exists(dir / "plots" / "mean_coverage_vs_controller.strategy_paired.png"));
}

}  // namespace
}  // namespace argus::report
