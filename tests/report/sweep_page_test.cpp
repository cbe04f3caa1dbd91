#include "report/sweep_page.hpp"

#include <gtest/gtest.h>

namespace argus::report {
namespace {

std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

// Three seeds at two values of a strategy; the oracle is higher in every seed, so its interval
// leaves out zero for coverage; the messages differ both ways. One run never happened.
sweep_results example() {
  sweep_results r;
  r.scenario = "a<b>.yaml";
  r.seeds = 3;
  r.parameters = {{"controller.strategy", {"paper", "oracle"}}};
  auto summary = [](double coverage, int messages) {
    return nlohmann::json{{"mean_coverage", coverage}, {"messages", messages}};
  };
  r.runs = {{"paper__seed=1", {"paper"}, 1, 0, 1.0, summary(0.2, 10)},
            {"paper__seed=2", {"paper"}, 2, 0, 1.0, summary(0.4, 20)},
            {"paper__seed=3", {"paper"}, 3, 0, 1.0, summary(0.3, 30)},
            {"oracle__seed=1", {"oracle"}, 1, 0, 1.0, summary(0.9, 5)},
            {"oracle__seed=2", {"oracle"}, 2, 0, 1.0, summary(0.95, 40)},
            {"oracle__seed=3", {"oracle"}, 3, std::nullopt, 0.0, nullptr}};
  return r;
}

TEST(sweep_page, leads_with_the_compare_metric_and_its_paired_difference) {
  const auto html = render_sweep_page(example(), {});
  EXPECT_NE(html.find("<title>Sweep of a&lt;b&gt;.yaml</title>"), std::string::npos);
  EXPECT_NE(html.find("<h2>mean_coverage by controller.strategy</h2>"), std::string::npos);
  EXPECT_NE(html.find("<td colspan=\"6\">baseline</td>"), std::string::npos);
  // oracle - paper over the two seeds both ran: +0.7 and +0.55.
  EXPECT_NE(html.find("<td class=\"number\">+0.625</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"number\">2 / 0 / 0</td>"), std::string::npos);
  EXPECT_NE(html.find("6 runs, 5 done, 0 failed"), std::string::npos);
  EXPECT_NE(html.find("<td>not done</td>"), std::string::npos);
  // The page checks itself in the browser, as report.html does.
  EXPECT_NE(html.find("id=\"status\" data-ready=\"no\""), std::string::npos);
}

TEST(sweep_page, marks_the_differences_whose_interval_leaves_out_zero) {
  auto r = example();
  r.runs[5] = {"oracle__seed=3",
               {"oracle"},
               3,
               0,
               1.0,
               nlohmann::json{{"mean_coverage", 0.9}, {"messages", 31}}};
  const auto html = render_sweep_page(r, {});
  // coverage: +0.7, +0.55, +0.6, clear of zero; messages: -5, +20, +1, not.
  EXPECT_EQ(count_of(html, "<tr class=\"clear\"><td>mean_coverage</td>"), 1u);
  EXPECT_EQ(count_of(html, "<tr class=\"clear\"><td>messages</td>"), 0u);
  EXPECT_EQ(count_of(html, "<tr><td>messages</td>"), 1u);
}

TEST(sweep_page, inlines_each_plot_once_the_compare_metric_s_first) {
  const std::vector<unsigned char> png{0x89, 'P', 'N', 'G'};
  const std::vector<report_image> plots{
      {"plots/messages_vs_controller.strategy.png", "messages vs controller.strategy", png, {}},
      {"plots/mean_coverage_vs_controller.strategy.png",
       "mean_coverage vs controller.strategy",
       png,
       {}},
      {"plots/mean_coverage_vs_controller.strategy_paired.png",
       "mean_coverage vs controller.strategy, paired",
       png,
       {}}};
  const auto html = render_sweep_page(example(), plots);
  EXPECT_EQ(count_of(html, "<img src=\"data:image/png;base64,"), 3u);
  const auto coverage = html.find("plots/mean_coverage_vs_controller.strategy.png");
  const auto paired = html.find("plots/mean_coverage_vs_controller.strategy_paired.png");
  const auto messages = html.find("plots/messages_vs_controller.strategy.png");
  ASSERT_NE(messages, std::string::npos);
  EXPECT_LT(coverage, paired);
  EXPECT_LT(paired, messages);  // the other metrics' plots come folded, after the tables
  EXPECT_LT(html.find("<details><summary>Every metric"), messages);
}

}  // namespace
}  // namespace argus::report
