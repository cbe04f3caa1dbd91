#include "report/key_frames.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "fmt/format.h"

namespace argus::report {
namespace {

// A run's log by hand: a task, a hand-off and the lead passing on, a crash, a link fault (not
// a camera failure), a crash of a camera already down (not applied) and a recovery.
const char* const story = R"({"t":0,"tick":0,"source":"camera/7","kind":"node_up","camera":7}
{"t":10,"tick":150,"source":"script","kind":"task_issued","task":0,"pedestrian":12,"camera":7}
{"t":10,"tick":150,"source":"camera/7","kind":"task_created","camera":7,"task":0}
{"t":13.2,"tick":198,"source":"camera/6","kind":"joined","camera":6,"task":0,"leader":7}
{"t":30,"tick":450,"source":"camera/7","kind":"handoff","camera":7,"task":0,"from":7,"to":6}
{"t":30.5,"tick":458,"source":"camera/6","kind":"leader_changed","camera":6,"task":0,"leader":6,"previous":7,"reason":"handover"}
{"t":40,"tick":600,"source":"faults","kind":"fault","fault":"crash","camera":6,"random":true,"applied":true}
{"t":41,"tick":615,"source":"faults","kind":"fault","fault":"crash","camera":6,"random":true,"applied":false}
{"t":45,"tick":675,"source":"faults","kind":"fault","fault":"crash_and_recover","camera":10,"applied":true}
{"t":47,"tick":705,"source":"faults","kind":"node_recovered","camera":10,"applied":true}
{"t":50,"tick":750,"source":"faults","kind":"fault","fault":"link_cut","camera":2,"peer":10,"applied":true}
)";

TEST(key_frames, picks_task_starts_handoffs_leader_changes_failures_and_recoveries) {
  const auto events = key_events_of(event_log::parse(story));
  ASSERT_EQ(events.size(), 6u);
  EXPECT_EQ(events[0].kind, "task_created");
  EXPECT_EQ(events[0].task, 0);
  ASSERT_EQ(events[0].frames.size(), 1u);
  EXPECT_EQ(events[0].frames[0].camera, 7);
  // The camera's turn at clock tick 150 looked at world tick 151.
  EXPECT_EQ(events[0].frames[0].world_tick, 151);
  EXPECT_FALSE(events[0].frames[0].failed);

  EXPECT_EQ(events[1].kind, "handoff");
  EXPECT_EQ(events[1].detail, "7 -> 6");
  ASSERT_EQ(events[1].frames.size(), 2u);
  EXPECT_EQ(events[1].frames[0].camera, 7);
  EXPECT_EQ(events[1].frames[1].camera, 6);

  EXPECT_EQ(events[2].kind, "leader_changed");
  EXPECT_EQ(events[2].detail, "leader 6 (was 7, handover)");
  EXPECT_EQ(events[2].frames[0].camera, 6);

  // The crash strikes before the cameras' phase: the last frame is world tick 600.
  EXPECT_EQ(events[3].kind, "camera_failed");
  EXPECT_EQ(events[3].task, -1);
  EXPECT_EQ(events[3].frames[0].camera, 6);
  EXPECT_EQ(events[3].frames[0].world_tick, 600);
  EXPECT_TRUE(events[3].frames[0].failed);

  EXPECT_EQ(events[4].kind, "camera_failed");
  EXPECT_EQ(events[4].frames[0].camera, 10);
  EXPECT_EQ(events[5].kind, "camera_recovered");
  EXPECT_EQ(events[5].frames[0].world_tick, 706);
  EXPECT_FALSE(events[5].frames[0].failed);
}

TEST(key_frames, in_time_order_whatever_the_logs_order) {
  const auto events = key_events_of(event_log::parse(
      R"({"t":4,"tick":60,"kind":"task_created","camera":3,"task":1}
{"t":2,"tick":30,"kind":"task_created","camera":2,"task":0}
{"t":4,"tick":60,"kind":"handoff","task":1,"from":3,"to":4}
)"));
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].task, 0);
  EXPECT_EQ(events[1].kind, "task_created");
  EXPECT_EQ(events[2].kind, "handoff");
}

TEST(key_frames, events_without_tick_or_camera_are_skipped) {
  const auto events = key_events_of(event_log::parse(
      R"({"t":1,"kind":"task_created","camera":7,"task":0}
{"t":2,"tick":30,"kind":"task_created","task":0}
{"t":3,"tick":45,"kind":"handoff","task":0,"from":7}
{"t":4,"tick":60,"kind":"fault","fault":"crash"}
)"));
  EXPECT_TRUE(events.empty());
}

std::vector<key_event> one_frame_events(int n) {
  std::string text;
  for (int k = 0; k < n; ++k)
    text += fmt::format(R"({{"t":{},"tick":{},"kind":"task_created","camera":{},"task":{}}})", k,
                        15 * k, 1 + k % 5, k) +
            "\n";
  return key_events_of(event_log::parse(text));
}

TEST(key_frames, all_events_when_their_frames_fit) {
  auto selection = select_key_events(one_frame_events(48), 48);
  EXPECT_EQ(selection.shown.size(), 48u);
  EXPECT_EQ(selection.events_left_out, 0u);
  EXPECT_EQ(selection.frames_left_out, 0u);
}

TEST(key_frames, the_cap_spreads_the_frames_evenly_over_the_run) {
  auto selection = select_key_events(one_frame_events(200), 48);
  ASSERT_EQ(selection.shown.size(), 48u);
  EXPECT_EQ(selection.events_left_out, 152u);
  EXPECT_EQ(selection.frames_left_out, 152u);
  // The first and the last event are in, and no two chosen ones are far apart: not the first 48.
  EXPECT_EQ(selection.shown.front().task, 0);
  EXPECT_EQ(selection.shown.back().task, 199);
  for (std::size_t k = 1; k < selection.shown.size(); ++k) {
    const int step = selection.shown[k].task - selection.shown[k - 1].task;
    EXPECT_GE(step, 4) << "at " << k;
    EXPECT_LE(step, 5) << "at " << k;
  }
}

TEST(key_frames, a_handoffs_two_frames_count_against_the_cap_and_stay_together) {
  std::string text;
  for (int k = 0; k < 40; ++k)
    text +=
        fmt::format(R"({{"t":{},"tick":{},"kind":"handoff","camera":1,"task":{},"from":1,"to":2}})",
                    k, 15 * k, k) +
        "\n";
  const auto selection = select_key_events(key_events_of(event_log::parse(text)), 48);
  // 40 events of two frames each: at most 24 events fit in 48 frames.
  EXPECT_EQ(selection.shown.size(), 24u);
  std::size_t frames = 0;
  for (const auto& e : selection.shown) {
    EXPECT_EQ(e.frames.size(), 2u);
    frames += e.frames.size();
  }
  EXPECT_EQ(frames, 48u);
  EXPECT_EQ(selection.events_left_out, 16u);
  EXPECT_EQ(selection.frames_left_out, 32u);
  EXPECT_EQ(selection.shown.front().task, 0);
  EXPECT_EQ(selection.shown.back().task, 39);
}

TEST(key_frames, a_cap_of_zero_shows_nothing) {
  const auto selection = select_key_events(one_frame_events(3), 0);
  EXPECT_TRUE(selection.shown.empty());
  EXPECT_EQ(selection.frames_left_out, 3u);
}

}  // namespace
}  // namespace argus::report
