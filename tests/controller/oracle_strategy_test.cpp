// The oracle strategy against a scripted view of ground truth: it joins and leaves tasks as the
// central assignment says, points where the truth says she is, takes her signature from its own
// view the first time (an acquire request) and then looks for her with it.

#include "controller/oracle_strategy.hpp"

#include <gtest/gtest.h>

namespace argus::controller {
namespace {

class scripted_view final : public oracle_view {
 public:
  std::optional<task_id> task_of(std::int64_t) override { return assigned; }
  vision::ptz_state pose_on(task_id, bool zoom) override { return {10.0, -5.0, zoom ? 8.0 : 40.0}; }
  std::optional<cv::Rect2d> target_box(task_id, const vision::ptz_state&) override { return box; }
  std::optional<protocol::signature> picked_signature(task_id) override { return picked; }
  void put_picked_signature(task_id task, protocol::signature s) override {
    put.emplace_back(task, std::move(s));
  }
  std::optional<task_id> assigned;
  std::optional<cv::Rect2d> box = cv::Rect2d(100, 50, 20, 60);
  std::optional<protocol::signature> picked;
  std::vector<std::pair<task_id, protocol::signature>> put;
};

node_identity camera_3() {
  node_identity me;
  me.id = 3;
  me.home = {45.0, -10.0, 50.0};
  return me;
}

TEST(oracle_strategy, follows_the_assignment_and_its_own_signature) {
  auto view = std::make_unique<scripted_view>();
  auto* truth = view.get();
  oracle_strategy oracle(camera_3(), config::scenario{}, std::move(view));
  // Unassigned: no frame wanted, home pose.
  EXPECT_FALSE(oracle.plan(1, false).wants_frame);
  controller_input in;
  in.tick = 1;
  EXPECT_EQ(oracle.step(in).command, camera_3().home);
  EXPECT_EQ(oracle.status().state, node_state::idle);
  // Assigned task 4: joins, wants the frame, points and asks for her signature from the box.
  truth->assigned = 4;
  auto plan = oracle.plan(2, false);
  EXPECT_TRUE(plan.wants_frame);
  ASSERT_EQ(plan.events.size(), 1u);
  EXPECT_EQ(plan.events[0].kind, "joined");
  in.tick = 2;
  in.sensed = true;
  auto out = oracle.step(in);
  EXPECT_EQ(out.command, (vision::ptz_state{10.0, -5.0, 8.0}));
  ASSERT_EQ(out.acquire.size(), 1u);
  EXPECT_EQ(out.acquire[0].task, 4u);
  EXPECT_EQ(out.acquire[0].box, *truth->box);
  EXPECT_TRUE(out.looks.empty());
  EXPECT_EQ(oracle.status().state, node_state::performing_task);
  // The signature comes back: from now on it looks for her with it, and asks no more.
  protocol::signature sig;
  sig.values = {0.5f, 0.25f};
  in.acquired = {{4, sig}};
  oracle.plan(3, true);
  out = oracle.step(in);
  EXPECT_TRUE(out.acquire.empty());
  ASSERT_EQ(out.looks.size(), 1u);
  EXPECT_EQ(out.looks[0].target, sig);
  // Unassigned again: leaves, home.
  truth->assigned.reset();
  plan = oracle.plan(4, true);
  ASSERT_EQ(plan.events.size(), 1u);
  EXPECT_EQ(plan.events[0].kind, "left_task");
  in.acquired.clear();
  in.sensed = false;
  EXPECT_EQ(oracle.step(in).command, camera_3().home);
}

TEST(oracle_strategy, with_the_operators_signature_passes_the_pick_on_and_looks_with_it) {
  auto view = std::make_unique<scripted_view>();
  auto* truth = view.get();
  auto s = config::scenario{};
  s.controller.oracle_signature_from = config::oracle_signature::operator_pick;
  oracle_strategy oracle(camera_3(), s, std::move(view));
  EXPECT_TRUE(oracle.takes_operator_signatures());
  controller_input in;
  operator_query q;
  q.task.task = 4;
  q.task.target.values = {0.75f};
  in.queries = {q};
  oracle.step(in);
  ASSERT_EQ(truth->put.size(), 1u);
  EXPECT_EQ(truth->put[0].first, 4u);
  truth->assigned = 4;
  truth->picked = q.task.target;
  oracle.plan(5, false);
  in = {};
  in.sensed = true;
  const auto out = oracle.step(in);
  EXPECT_TRUE(out.acquire.empty());
  ASSERT_EQ(out.looks.size(), 1u);
  EXPECT_EQ(out.looks[0].target, q.task.target);
}

}  // namespace
}  // namespace argus::controller
