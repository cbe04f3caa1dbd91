#include "report/html_report.hpp"

#include <gtest/gtest.h>

namespace argus::report {
namespace {

TEST(html_report, escapes_text_and_keeps_the_event_log_inside_its_element) {
  const auto log =
      event_log::parse(R"({"t":1.0,"kind":"note","text":"</script><script>alert(1)</script>"})"
                       "\n");
  html_report_input input;
  input.title = "run <1> & \"two\"";
  input.events = &log;
  const auto html = render_html_report(input);
  EXPECT_NE(html.find("<title>run &lt;1&gt; &amp; &quot;two&quot;</title>"), std::string::npos);
  EXPECT_EQ(html.find("alert(1)</script>"), std::string::npos);
  EXPECT_NE(html.find("\\u003c/script>\\u003cscript>alert(1)"), std::string::npos);
}

TEST(html_report, images_inline_and_metrics_tables) {
  html_report_input input;
  input.title = "t";
  input.images.push_back({"plan.png", "the plan", {'f', 'o', 'o'}, {}});
  input.metrics = nlohmann::json::parse(
      R"({"summary":{"mean_coverage":0.5,"mean_coverage_of_oracle":null},
          "tasks":[{"task":0,"group_size":{"mean":1.5,"max":2,"series":[[0,1]]},"handoff_gaps_s":[1,2]}]})");
  const auto html = render_html_report(input);
  EXPECT_NE(html.find("src=\"data:image/png;base64,Zm9v\""), std::string::npos);
  EXPECT_NE(html.find("<th>mean_coverage</th><td class=\"number\">0.5</td>"), std::string::npos);
  EXPECT_NE(html.find("<th>mean_coverage_of_oracle</th><td>&ndash;</td>"), std::string::npos);
  EXPECT_NE(html.find("<th>group_size.mean</th>"), std::string::npos);
  EXPECT_NE(html.find("<td>2 entries</td>"), std::string::npos);
  EXPECT_EQ(html.find("http://"), std::string::npos);  // nothing fetched
  EXPECT_EQ(html.find("https://"), std::string::npos);
}

TEST(html_report, a_contact_sheet_lists_its_frames_under_it) {
  html_report_input input;
  input.images.push_back({"feeds/contact_sheet.png",
                          "the cameras' frames at the key events",
                          {'f', 'o', 'o'},
                          {"feeds/t0016.00_task_created_cam7.png: 16.00 s  task start",
                           "feeds/t0030.00_handoff_cam7.png: 7 -> 6 <gives>"}});
  const auto html = render_html_report(input);
  EXPECT_NE(html.find("<figcaption>feeds/contact_sheet.png: the cameras&#39; frames at the key "
                      "events</figcaption><details><summary>2 frames</summary><ol>"),
            std::string::npos);
  EXPECT_NE(html.find("<li>feeds/t0030.00_handoff_cam7.png: 7 -&gt; 6 &lt;gives&gt;</li>"),
            std::string::npos);
}

TEST(html_report, holds_at_most_max_events_and_says_so) {
  const auto log = event_log::parse(
      "{\"t\":1.0,\"kind\":\"a\"}\n{\"t\":2.0,\"kind\":\"b\"}\n{\"t\":3.0,\"kind\":\"c\"}\n");
  html_report_input input;
  input.events = &log;
  input.max_events = 2;
  const auto html = render_html_report(input);
  EXPECT_NE(html.find("the first 2 of the run's 3 events"), std::string::npos);
  EXPECT_NE(html.find("\"kind\":\"b\""), std::string::npos);
  EXPECT_EQ(html.find("\"kind\":\"c\""), std::string::npos);
}

TEST(html_report, says_what_is_missing) {
  const auto html = render_html_report({});
  EXPECT_NE(html.find("No metrics.json"), std::string::npos);
  EXPECT_NE(html.find("No events.jsonl"), std::string::npos);
}

}  // namespace
}  // namespace argus::report
