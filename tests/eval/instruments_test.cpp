// The evaluation's instruments as wrappers around a sensor or a strategy they know nothing
// else of (eval/instruments.hpp): what each lets through, records or changes, on fakes.

#include <gtest/gtest.h>

#include "eval/frame_recording.hpp"
#include "eval/oracle_assignment.hpp"
#include "eval/sighting_aim.hpp"
#include "eval/truth_identity.hpp"
#include "world/layout_loader.hpp"

namespace argus::eval {
namespace {

// A sensor that weighs the candidates it is given, each as task 7's, and reports which the
// filters admitted.
class weighing_sensor final : public sensing::sensor {
 public:
  explicit weighing_sensor(std::vector<sensing::candidate> candidates)
      : candidates_(std::move(candidates)) {}
  bool needs_image() const override { return false; }
  std::vector<controller::look_result> look(const sensing::sensed_frame&,
                                            const std::vector<controller::look_request>&,
                                            const sensing::candidate_filter& admit) override {
    admitted.clear();
    for (const auto& c : candidates_) admitted.push_back(!admit || admit(c));
    return {};
  }
  bool can_acquire(const sensing::sensed_frame&) const override { return true; }
  protocol::signature acquire(controller::task_id, const sensing::sensed_frame&,
                              const cv::Rect2d&) override {
    return {};
  }
  std::vector<bool> admitted;

 private:
  std::vector<sensing::candidate> candidates_;
};

// A strategy whose status and output the test sets.
class scripted final : public controller::strategy {
 public:
  controller::controller_output step(const controller::controller_input&) override {
    ++steps;
    return output;
  }
  controller::strategy_status status() const override { return state; }
  controller::strategy_status state;
  controller::controller_output output;
  int steps = 0;
};

config::camera_settings camera_5() {
  config::camera_settings c;
  c.id = 5;
  c.position = {100, 30};
  c.height_m = 6.0;
  c.pan_deg = 135;
  c.imaging.width_px = 320;
  c.imaging.height_px = 240;
  return c;
}

world::pedestrian_state standing(int id, double x, double y) {
  world::pedestrian_state p;
  p.id = id;
  p.position = {x, y};
  p.look.shirt = {200, 30, 30};
  return p;
}

struct truth_fixture : ::testing::Test {
  std::shared_ptr<const world::station> station =
      world::station::load(world::layout_path(config::scenario{}));
  std::shared_ptr<const world::snapshot> now = std::make_shared<const world::snapshot>(
      *station, 40, std::chrono::duration<double>{40.0 / 15.0},
      std::vector<world::pedestrian_state>{standing(1, 85, 50), standing(2, 88, 52)});
  std::shared_ptr<observation_log> log = std::make_shared<observation_log>();

  std::shared_ptr<const camera_truth> truth() {
    auto t = std::make_shared<camera_truth>();
    t->camera = camera_5();
    t->station = station;
    t->now = [frame = now] { return frame; };
    t->log = log;
    return t;
  }
};

using truth_identity_test = truth_fixture;

TEST_F(truth_identity_test, admits_only_the_tasks_own_pedestrian_and_still_asks_the_outer_filter) {
  log->add_origin({7, 1, 5, 0, target_choice::pedestrian});
  auto inner = std::make_unique<weighing_sensor>(std::vector<sensing::candidate>{
      {7, std::nullopt, 1}, {7, std::nullopt, 2}, {8, std::nullopt, 1}});
  auto* weighed = inner.get();
  truth_identity sensor(std::move(inner), truth());
  sensing::sensed_frame frame;
  frame.truth = now;
  frame.station = station;
  sensor.look(frame, {});
  // Hers; someone else; a task whose target is unknown.
  EXPECT_EQ(weighed->admitted, (std::vector<bool>{true, false, false}));
  sensor.look(frame, {}, [](const sensing::candidate&) { return false; });
  EXPECT_EQ(weighed->admitted, (std::vector<bool>{false, false, false}));
}

using frame_recording_test = truth_fixture;

TEST_F(frame_recording_test, records_the_groups_looks_and_the_messages_by_task) {
  log->add_origin({7, 1, 5, 0, target_choice::pedestrian});
  auto inner = std::make_unique<scripted>();
  inner->state.state = controller::node_state::performing_task;
  inner->state.task = 7;
  inner->state.role = controller::group_role::leader;
  protocol::status heartbeat;
  heartbeat.task = 7;
  inner->output.messages.push_back({protocol::broadcast, heartbeat});
  auto* script = inner.get();
  frame_recording recorder(std::move(inner), truth());
  controller::controller_input in;
  in.tick = 40;
  in.pose = {135.0, -10.0, 45.0};
  in.looks = {{7, false, {}, 0.2, std::nullopt}, {9, false, {}, 0.1, std::nullopt}};
  recorder.step(in);
  EXPECT_EQ(script->steps, 1);
  auto recorded = log->take();
  ASSERT_EQ(recorded.frames[5].size(), 1u);
  const auto& f = recorded.frames[5][0];
  EXPECT_EQ(f.tick, 40);
  EXPECT_EQ(f.state, frame_state::performing_task);
  EXPECT_EQ(f.pose.pan_deg, 135.0);
  // A bidder's look (task 9) is not the group's.
  ASSERT_EQ(f.looks.size(), 1u);
  EXPECT_TRUE(f.looks[0].leader);
  EXPECT_EQ(f.looks[0].score, 0.2);
  EXPECT_EQ((recorded.sent[{7, "status"}]), 1u);
}

using sighting_aim_test = truth_fixture;

TEST_F(sighting_aim_test, points_a_camera_that_lost_her_at_whom_its_group_holds) {
  auto board = std::make_shared<sighting_board>();
  board->put(39, 7, 3, true, 2);  // camera 3, the leader, held pedestrian 2 in the last frame
  auto inner = std::make_unique<scripted>();
  inner->state.state = controller::node_state::performing_task;
  inner->state.task = 7;
  inner->state.tracking = vision::tracking_state::wait;
  auto* script = inner.get();
  sighting_aim aim(std::move(inner), truth(), board, true, false);
  controller::controller_input in;
  in.tick = 40;
  in.sensed = true;
  const auto out = aim.step(in);
  ASSERT_TRUE(out.command);
  EXPECT_EQ(*out.command, oracle_pose(camera_5(), *now, 2));
  // Tracking, it follows its own tracker; with no frame this tick, it is left alone.
  script->state.tracking = vision::tracking_state::track;
  EXPECT_FALSE(aim.step(in).command);
  script->state.tracking = vision::tracking_state::search;
  in.sensed = false;
  EXPECT_FALSE(aim.step(in).command);
}

}  // namespace
}  // namespace argus::eval
