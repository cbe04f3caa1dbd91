// Every metric of docs/metrics.md on a hand-built trace whose answer is known: a target in the
// main waiting room for ten ticks, camera 1 tracking her, confusing her with someone else,
// crashing, and camera 2 taking over after a gap.

#include "eval/metrics.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "config/scenario_loader.hpp"
#include "eval/reachability.hpp"
#include "nlohmann/json.hpp"
#include "world/layout_loader.hpp"
#include "world/station.hpp"

namespace argus::eval {
namespace {

constexpr int target = 12;
constexpr int someone_else = 99;

look_record look(bool found, int truth, bool observed, double iou) {
  look_record l;
  l.task = 0;
  l.found = found;
  l.box = cv::Rect2d(10, 10, 20, 60);
  l.truth = truth;
  l.observed = observed;
  l.iou = iou;
  return l;
}

camera_frame frame(int camera, std::int64_t tick, std::vector<look_record> looks = {}) {
  camera_frame f;
  f.camera = camera;
  f.tick = tick;
  f.looks = std::move(looks);
  return f;
}

struct trace : ::testing::Test {
  config::scenario scenario = config::load_scenario(std::filesystem::path(ARGUS_SOURCE_DIR) /
                                                    "scenarios/penn_station.yaml");
  std::shared_ptr<const world::station> station =
      world::station::load(world::layout_path(scenario));
  observation_log::contents log;
  std::vector<logged_event> events;

  void SetUp() override {
    log.origins.push_back({0, target, 1, 1, target_choice::pedestrian});
    for (std::int64_t t = 1; t <= 11; ++t)
      log.samples.push_back({t, 0, target, 85.0, 50.0, 1.7, t <= 10});
    // Camera 1: observes her in ticks 1-4, holds someone else in 5-6, then crashes (tick 7).
    for (std::int64_t t = 1; t <= 4; ++t)
      log.frames[1].push_back(frame(1, t, {look(true, target, true, t == 1 ? 0.6 : 0.3)}));
    for (std::int64_t t = 5; t <= 6; ++t)
      log.frames[1].push_back(frame(1, t, {look(true, someone_else, false, 0.0)}));
    // Camera 2: alive throughout, in the group from tick 8.
    for (std::int64_t t = 1; t <= 7; ++t) log.frames[2].push_back(frame(2, t));
    for (std::int64_t t = 8; t <= 11; ++t)
      log.frames[2].push_back(frame(2, t, {look(true, target, true, 0.7)}));
    log.sent[{0, "queryrelevance"}] = 3;
    log.sent[{0, "status"}] = 7;
    log.sent[{1, "status"}] = 100;  // another task's
    events.push_back({7, 7.0 / 15.0,
                      events::fault_event{.fault = "crash",
                                          .camera = 1,
                                          .peer = std::nullopt,
                                          .random = false,
                                          .applied = true}});
    events::leader_changed changed;
    changed.camera = 2;
    changed.task = 0;
    events.push_back({8, 8.0 / 15.0, changed});
    events::handoff handoff;
    handoff.camera = 1;
    handoff.task = 0;
    events.push_back({3, 3.0 / 15.0, handoff});
    handoff.task = 5;
    events.push_back({3, 3.0 / 15.0, handoff});  // another task's
    events::conflict conflict;
    conflict.camera = 4;
    conflict.task = 5;
    conflict.with_tasks = {0};
    events.push_back({5, 5.0 / 15.0, conflict});
  }
};

TEST_F(trace, the_waiting_room_is_in_reach_of_its_cameras_and_the_arcade_is_not) {
  const auto& c1 = scenario.cameras[0];
  ASSERT_EQ(c1.id, 1);
  EXPECT_TRUE(reachable(c1, *station, world::vec2{85.0, 50.0}, 1.7));
  EXPECT_FALSE(reachable(c1, *station, world::vec2{185.0, 50.0}, 1.7));
}

TEST_F(trace, every_metric_has_its_known_value) {
  const auto result = evaluate(scenario, *station, log, events, 100);
  ASSERT_EQ(result.tasks.size(), 1u);
  const auto& m = result.tasks[0];
  const double tick = 1.0 / 15.0;
  EXPECT_EQ(m.end_reason, "left_station");
  EXPECT_NEAR(m.start_s, tick, 1e-9);
  EXPECT_NEAR(m.end_s, 11 * tick, 1e-9);
  EXPECT_NEAR(m.time_in_station_s, 10 * tick, 1e-9);
  EXPECT_NEAR(m.coverage, 0.7, 1e-9);        // ticks 1-4 and 8-10
  EXPECT_NEAR(m.coverage_iou50, 0.4, 1e-9);  // tick 1 and 8-10
  // Ticks 5 and 6: camera 1 holds someone else; tick 7: camera 1 is down, camera 2 not yet in.
  EXPECT_NEAR(m.uncovered.other_person, 0.2, 1e-9);
  EXPECT_NEAR(m.uncovered.no_camera, 0.1, 1e-9);
  EXPECT_EQ(m.uncovered.off_her + m.uncovered.background + m.uncovered.lost, 0.0);
  ASSERT_TRUE(m.correct_identity);
  EXPECT_NEAR(*m.correct_identity, 7.0 / 9.0, 1e-9);
  EXPECT_NEAR(m.oracle_bound, 1.0, 1e-9);
  ASSERT_TRUE(m.coverage_of_oracle);
  EXPECT_NEAR(*m.coverage_of_oracle, 0.7, 1e-9);
  EXPECT_EQ(m.handoffs, 1);
  EXPECT_EQ(m.observation_handoffs, 1);
  ASSERT_EQ(m.handoff_gaps_s.size(), 1u);
  EXPECT_NEAR(m.handoff_gaps_s[0], 3 * tick, 1e-9);  // ticks 5, 6 and 7
  EXPECT_EQ(m.identity_switches, 1);
  EXPECT_EQ(m.group_size_max, 1);
  EXPECT_NEAR(m.group_size_mean, 0.9, 1e-9);
  ASSERT_EQ(m.group_size_series.size(), 3u);
  EXPECT_EQ(m.group_size_series[1].second, 0);
  EXPECT_NEAR(m.group_size_series[1].first, 7 * tick, 1e-9);
  EXPECT_EQ(m.leader_changes, 1);
  EXPECT_EQ(m.csp_invocations, 1);
  EXPECT_EQ(m.messages_by_kind.at("queryrelevance"), 3u);
  EXPECT_EQ(m.messages_by_kind.at("status"), 7u);
  ASSERT_EQ(m.failure_recoveries.size(), 1u);
  EXPECT_EQ(m.failure_recoveries[0].camera, 1);
  ASSERT_TRUE(m.failure_recoveries[0].recovered_after_s);
  EXPECT_NEAR(*m.failure_recoveries[0].recovered_after_s, tick, 1e-9);
  // targets.csv's rows: who observed her when.
  ASSERT_EQ(result.targets.size(), 11u);
  EXPECT_EQ(result.targets[0].observed_by, 1);
  EXPECT_EQ(result.targets[5].observed_by, -1);
  EXPECT_EQ(result.targets[8].observed_by, 2);
  EXPECT_FALSE(result.targets[10].sample.present);
}

TEST_F(trace, a_cancelled_task_ends_at_the_cancellation) {
  log.cancels[0] = 6;
  const auto m = evaluate(scenario, *station, log, events, 100).tasks.at(0);
  EXPECT_EQ(m.end_reason, "cancelled");
  EXPECT_NEAR(m.coverage, 0.8, 1e-9);  // ticks 1-4 of 1-5
  EXPECT_TRUE(m.failure_recoveries.empty());
}

TEST_F(trace, each_uncovered_tick_goes_to_the_first_cause_that_holds_in_it) {
  // Tick 5: camera 1's box on a part of her it does not contain; tick 6: on the floor; tick 7:
  // camera 2 in the group but lost, camera 1 down.
  log.frames[1][4] = frame(1, 5, {look(true, target, false, 0.1)});
  log.frames[1][5] = frame(1, 6, {look(true, -1, false, 0.0)});
  log.frames[2][6] = frame(2, 7, {look(false, -1, false, 0.0)});
  // Tick 4: someone else beside her correct box still counts as covered.
  log.frames[2][3] = frame(2, 4, {look(true, someone_else, false, 0.0)});
  const auto m = evaluate(scenario, *station, log, events, 100).tasks.at(0);
  EXPECT_NEAR(m.coverage, 0.7, 1e-9);
  EXPECT_NEAR(m.uncovered.off_her, 0.1, 1e-9);
  EXPECT_NEAR(m.uncovered.background, 0.1, 1e-9);
  EXPECT_NEAR(m.uncovered.lost, 0.1, 1e-9);
  EXPECT_EQ(m.uncovered.other_person + m.uncovered.no_camera, 0.0);
}

TEST_F(trace, the_json_names_every_figure_and_the_summary_averages_tasks) {
  const auto result = evaluate(scenario, *station, log, events, 100);
  const auto j = metrics_json(scenario, result, 2.0, 10.0);
  EXPECT_EQ(j["strategy"], "paper");
  EXPECT_EQ(j["summary"]["tasks"], 1);
  EXPECT_NEAR(j["summary"]["mean_coverage"].get<double>(), 0.7, 1e-9);
  EXPECT_NEAR(j["summary"]["speed_ratio"].get<double>(), 5.0, 1e-9);
  EXPECT_EQ(j["tasks"][0]["messages"], 10);
  for (const auto* key :
       {"coverage", "coverage_iou50", "correct_identity", "oracle_bound", "coverage_of_oracle",
        "handoffs", "handoff_gaps_s", "identity_switches", "group_size", "leader_changes",
        "messages_by_kind", "csp_invocations", "failure_recoveries", "uncovered"})
    EXPECT_TRUE(j["tasks"][0].contains(key)) << key;
  EXPECT_NEAR(j["tasks"][0]["uncovered"]["other_person"].get<double>(), 0.2, 1e-9);
  EXPECT_NEAR(j["summary"]["mean_uncovered_other_person"].get<double>(), 0.2, 1e-9);
}

TEST_F(trace, the_summary_names_the_least_covered_task) {
  auto result = evaluate(scenario, *station, log, events, 100);
  EXPECT_NEAR(metrics_json(scenario, result, 2.0, 10.0)["summary"]["min_coverage"].get<double>(),
              0.7, 1e-9);
  auto second = result.tasks.at(0);
  second.task = 1;
  second.coverage = 0.25;
  result.tasks.push_back(second);
  const auto j = metrics_json(scenario, result, 2.0, 10.0);
  EXPECT_NEAR(j["summary"]["min_coverage"].get<double>(), 0.25, 1e-9);
  EXPECT_NEAR(j["summary"]["mean_coverage"].get<double>(), 0.475, 1e-9);
  result.tasks.clear();
  EXPECT_TRUE(metrics_json(scenario, result, 2.0, 10.0)["summary"]["min_coverage"].is_null());
}

}  // namespace
}  // namespace argus::eval
