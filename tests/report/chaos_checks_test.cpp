// argus chaos's invariants, on hand-made logs: each rule broken once must be caught, and a
// log of the protocol's ordinary life (hand-over, merge, conflict, crash) must pass.

#include "report/chaos_checks.hpp"

#include <gtest/gtest.h>

#include <string>

namespace argus::report {
namespace {

event_log log_of(const std::string& lines) {
  return event_log::parse(lines);
}

// Task 0's target is in the station and in some camera's reach from 50 s to 70 s.
csv_table reachable_target() {
  std::string text = "tick,t,task,pedestrian,x,y,present,reachable,observed_by\n";
  for (int t = 50; t <= 70; ++t)
    text += std::to_string(t * 10) + "," + std::to_string(t) + ",0,5,1,1,1,1,-1\n";
  return csv_table::parse(text);
}

chaos_bounds bounds() {
  chaos_bounds b;
  b.liveness_window_s = 10.0;
  return b;
}

const std::string ordinary =
    R"({"t":1,"kind":"task_created","camera":1,"task":0,"term":1})"
    "\n"
    R"({"t":2,"kind":"joined","camera":2,"task":0,"leader":1,"reassign":false,"term":1})"
    "\n"
    R"({"t":10,"kind":"handoff","camera":1,"task":0,"from":1,"to":2})"
    "\n"
    R"({"t":10.2,"kind":"leader_changed","camera":2,"task":0,"leader":2,"previous":1,"reason":"handover","term":2})"
    "\n"
    R"({"t":11,"kind":"left_task","camera":1,"task":0,"reason":"handed_over","role":"member"})"
    "\n"
    R"({"t":20,"kind":"task_created","camera":3,"task":0,"term":3})"
    "\n"
    R"({"t":21,"kind":"leader_changed","camera":2,"task":0,"leader":3,"previous":2,"reason":"newer_term","term":3})"
    "\n"
    R"({"t":30,"kind":"fault","camera":3,"fault":"crash","applied":true})"
    "\n"
    R"({"t":33,"kind":"leader_changed","camera":2,"task":0,"leader":2,"previous":3,"reason":"leader_failed","term":4})"
    "\n"
    R"({"t":40,"kind":"leader_changed","camera":2,"task":0,"leader":2,"previous":2,"reason":"merged","term":5})"
    "\n";

TEST(chaos_checks, the_protocols_ordinary_life_passes) {
  const auto v = check_chaos_log(log_of(ordinary), reachable_target(), 50.0, bounds());
  EXPECT_EQ(v.terms_broken, 0u);
  EXPECT_EQ(v.camera_in_two_groups, 0u);
  EXPECT_EQ(v.live_tasks, 1u);
  EXPECT_EQ(v.led_in_time, 1u);
  EXPECT_TRUE(v.live());
  EXPECT_TRUE(v.problems.empty());
}

TEST(chaos_checks, a_camera_that_enters_a_second_group_is_caught) {
  const auto v = check_chaos_log(
      log_of(ordinary +
             R"({"t":45,"kind":"joined","camera":2,"task":1,"leader":4,"reassign":false,"term":1})"
             "\n"),
      reachable_target(), 50.0, bounds());
  EXPECT_EQ(v.camera_in_two_groups, 1u);
  ASSERT_FALSE(v.problems.empty());
  EXPECT_NE(v.problems[0].find("camera 2 entered task 1"), std::string::npos) << v.problems[0];
}

TEST(chaos_checks, a_term_taken_up_again_is_caught) {
  // Camera 2 led task 0 at epoch 4 until it merged into epoch 5; it may not lead epoch 4 again.
  const auto v = check_chaos_log(
      log_of(ordinary +
             R"({"t":41,"kind":"left_task","camera":2,"task":0,"reason":"dropped","role":"leader"})"
             "\n"
             R"({"t":42,"kind":"task_created","camera":2,"task":0,"term":4})"
             "\n"),
      reachable_target(), 50.0, bounds());
  EXPECT_EQ(v.terms_broken, 1u);
}

TEST(chaos_checks, a_term_taken_up_again_after_a_crash_is_counted_apart) {
  // Camera 2 crashed after leading epoch 5, came back with nothing in memory and, never having
  // heard of epochs 4 and 5 from anyone, leads epoch 5 again.
  const auto v = check_chaos_log(
      log_of(ordinary +
             R"({"t":41,"kind":"fault","camera":2,"fault":"crash_and_recover","applied":true})"
             "\n"
             R"({"t":45,"kind":"task_created","camera":2,"task":0,"term":5})"
             "\n"),
      reachable_target(), 50.0, bounds());
  EXPECT_EQ(v.terms_broken, 0u);
  EXPECT_EQ(v.terms_reused_after_recovery, 1u);
}

TEST(chaos_checks, a_recovery_of_a_camera_that_was_up_changes_nothing) {
  // A second crash_and_recover's recovery for a camera that is up is logged, not applied.
  const auto v = check_chaos_log(
      log_of(
          ordinary +
          R"({"t":41,"kind":"node_recovered","camera":2,"applied":false})"
          "\n"
          R"({"t":42,"kind":"leader_changed","camera":2,"task":0,"leader":2,"previous":2,"reason":"merged","term":6})"
          "\n"),
      reachable_target(), 50.0, bounds());
  EXPECT_EQ(v.camera_in_two_groups, 0u);
  EXPECT_TRUE(v.problems.empty());
}

TEST(chaos_checks, an_epoch_that_goes_back_is_caught) {
  const auto v = check_chaos_log(
      log_of(
          ordinary +
          R"({"t":45,"kind":"leader_changed","camera":2,"task":0,"leader":7,"previous":2,"reason":"newer_term","term":3})"
          "\n"),
      reachable_target(), 50.0, bounds());
  EXPECT_EQ(v.terms_broken, 1u);
}

TEST(chaos_checks, two_leaderships_of_one_epoch_are_counted_not_failed) {
  const auto v =
      check_chaos_log(log_of(R"({"t":1,"kind":"task_created","camera":1,"task":0,"term":1})"
                             "\n"
                             R"({"t":2,"kind":"task_created","camera":2,"task":0,"term":1})"
                             "\n"),
                      reachable_target(), 50.0, bounds());
  EXPECT_EQ(v.same_epoch_leaderships, 1u);
  EXPECT_EQ(v.terms_broken, 0u);
}

// Camera 2 follows camera 3, which crashes at 30 s.
const std::string leader_crashed =
    R"({"t":1,"kind":"task_created","camera":3,"task":0,"term":1})"
    "\n"
    R"({"t":2,"kind":"joined","camera":2,"task":0,"leader":3,"reassign":false,"term":1})"
    "\n"
    R"({"t":30,"kind":"fault","camera":3,"fault":"crash","applied":true})"
    "\n";

TEST(chaos_checks, a_task_left_to_followers_after_the_faults_is_not_live) {
  // Camera 2 follows camera 3, which crashed at 30 s, and never takes over.
  const std::string orphaned = leader_crashed +
                               R"({"t":80,"kind":"node_state","camera":2,"state":"idle"})"
                               "\n";
  const auto v = check_chaos_log(log_of(orphaned), reachable_target(), 50.0, bounds());
  EXPECT_EQ(v.live_tasks, 1u);
  EXPECT_EQ(v.led_in_time, 0u);
  EXPECT_FALSE(v.live());
  // Out of every camera's reach, nobody could have led her: not counted.
  const auto unseen = check_chaos_log(
      log_of(orphaned), csv_table::parse("t,task,present,reachable\n"), 50.0, bounds());
  EXPECT_EQ(unseen.live_tasks, 0u);
  EXPECT_TRUE(unseen.live());
}

TEST(chaos_checks, a_leader_within_the_window_is_in_time) {
  const std::string late =
      leader_crashed +
      R"({"t":58,"kind":"leader_changed","camera":2,"task":0,"leader":2,"previous":3,"reason":"leader_failed","term":2})"
      "\n";
  const auto v = check_chaos_log(log_of(late), reachable_target(), 50.0, bounds());
  EXPECT_EQ(v.led_in_time, 1u);
  EXPECT_TRUE(v.live());
}

TEST(chaos_checks, bounds_on_messages_and_memory) {
  chaos_verdict v;
  v.complete = true;
  chaos_bounds b;
  b.max_messages_per_task_s = 100;
  b.max_rss_kib = 1024;
  v.peak_messages_per_task_s = 100;
  v.peak_rss_kib = 1024;
  EXPECT_TRUE(v.safe(b));
  v.peak_messages_per_task_s = 101;
  EXPECT_FALSE(v.safe(b));
  v.peak_messages_per_task_s = 100;
  v.peak_rss_kib = 1025;
  EXPECT_FALSE(v.safe(b));
  v.peak_rss_kib = 1;
  v.messages_after_cancel = 1;
  EXPECT_FALSE(v.safe(b));
}

}  // namespace
}  // namespace argus::report
