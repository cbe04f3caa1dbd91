#include "report/group_timeline.hpp"

#include <gtest/gtest.h>

namespace argus::report {

bool operator==(const camera_span& a, const camera_span& b) {
  return a.camera == b.camera && a.from_s == b.from_s && a.to_s == b.to_s;
}

void PrintTo(const camera_span& s, std::ostream* out) {
  *out << "camera " << s.camera << " [" << s.from_s << ", " << s.to_s << ")";
}

namespace {

const std::filesystem::path data_dir{ARGUS_REPORT_TEST_DATA_DIR};

// The fixture's story (tests/report/data/run/events.jsonl):
//   task 0:  7 leads 10-30 | 6 joins 13.2, leads 30.5, crashes 40 | 2 joins 35, leads 43-70 |
//            10 joins 55, leads 70.4, loses her 110;  hand-overs at 30 and 70
//   task 1:  9 alone 90-100, cancelled at 100
//   faults:  crash 6 @40, crash_and_recover 10 @45 (back @47), link 2-10 cut @50, healed @52
group_timeline fixture() {
  const auto log = event_log::read(data_dir / "run" / "events.jsonl");
  EXPECT_TRUE(log);
  return group_timeline::from(*log, 120.0);
}

TEST(group_timeline, members_leaders_and_handoffs_of_a_task) {
  const auto timeline = fixture();
  ASSERT_EQ(timeline.tasks.size(), 2u);
  const auto& task = timeline.tasks[0];
  EXPECT_EQ(task.pedestrian, 12);
  EXPECT_DOUBLE_EQ(task.start_s, 10.0);
  EXPECT_DOUBLE_EQ(task.end_s, 120.0);  // never cancelled: open to the run's end
  EXPECT_EQ(task.members,
            (std::vector<camera_span>{
                {7, 10.0, 30.0}, {6, 13.2, 40.0}, {2, 35.0, 70.0}, {10, 55.0, 110.0}}));
  EXPECT_EQ(task.leaders,
            (std::vector<camera_span>{
                {7, 10.0, 30.0}, {6, 30.5, 40.0}, {2, 43.0, 70.0}, {10, 70.4, 110.0}}));
  EXPECT_EQ(task.handoffs_s, (std::vector<double>{30.0, 70.0}));
}

TEST(group_timeline, a_cancelled_task_ends_at_its_cancellation) {
  const auto timeline = fixture();
  const auto& task = timeline.tasks[1];
  EXPECT_EQ(task.pedestrian, 30);
  EXPECT_DOUBLE_EQ(task.end_s, 100.0);
  EXPECT_EQ(task.members, (std::vector<camera_span>{{9, 90.0, 100.0}}));
  EXPECT_EQ(task.leaders, (std::vector<camera_span>{{9, 90.0, 100.0}}));
}

TEST(group_timeline, failures_in_order_and_the_broken_last_line_skipped) {
  const auto timeline = fixture();
  ASSERT_EQ(timeline.failures.size(), 5u);
  EXPECT_EQ(timeline.failures[0].kind, "crash");
  EXPECT_EQ(timeline.failures[0].camera, 6);
  EXPECT_EQ(timeline.failures[2].kind, "recovered");
  EXPECT_DOUBLE_EQ(timeline.failures[2].t_s, 47.0);
  EXPECT_EQ(timeline.failures[4].kind, "link_heal");
}

TEST(group_timeline, open_spans_close_at_the_last_event_when_the_length_is_unknown) {
  const auto log = event_log::parse(R"({"t":1.0,"kind":"task_created","camera":3,"task":0})"
                                    "\n"
                                    R"({"t":4.0,"kind":"node_state","camera":3})"
                                    "\n");
  const auto timeline = group_timeline::from(log, 0.0);
  ASSERT_EQ(timeline.tasks.size(), 1u);
  EXPECT_EQ(timeline.tasks[0].pedestrian, -1);
  EXPECT_EQ(timeline.tasks[0].members, (std::vector<camera_span>{{3, 1.0, 4.0}}));
}

TEST(group_timeline, a_fault_not_applied_is_not_a_failure) {
  const auto log =
      event_log::parse(R"({"t":1.0,"kind":"fault","fault":"crash","camera":3,"applied":false})"
                       "\n");
  EXPECT_TRUE(group_timeline::from(log, 5.0).failures.empty());
}

}  // namespace
}  // namespace argus::report
