// controller.share_model: a leader whose tracker re-took its model of her makes that model the
// task's signature, carried by its next auction's queries; the paper's leader keeps sending the
// operator's pick.

#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "controller/camera_controller.hpp"
#include "protocol_harness.hpp"

namespace argus::controller::testing {
namespace {

// Camera 1 alone leads a task that wants two cameras, so it auctions again and again; it sees
// her centred in every frame, and in frame 5 its tracker re-takes its model as `zoomed`.
std::vector<protocol::query_relevance> queries_of_a_leader(bool share_model,
                                                           const protocol::signature& zoomed) {
  auto settings = test_scenario({1});
  settings.controller.share_model = share_model;
  camera_controller node(node_identity::from(settings.cameras.front()), settings);
  const auto task = test_task(2, 2);
  std::vector<protocol::query_relevance> queries;
  bool asked = false;
  for (std::int64_t tick = 0; tick < 150; ++tick) {
    controller_input in;
    in.tick = tick;
    in.pose = node_identity::from(settings.cameras.front()).home;
    if (tick == 0) in.queries.push_back({task, centred_box()});
    if (asked) {
      in.looks.push_back({task.task, true, centred_box(), 0.8, std::nullopt});
      if (tick == 5) in.looks.back().model = zoomed;
    }
    const auto out = node.step(in);
    asked = !out.looks.empty();
    for (const auto& m : out.messages)
      if (const auto* q = std::get_if<protocol::query_relevance>(&m.message)) queries.push_back(*q);
  }
  return queries;
}

protocol::signature zoomed_signature() {
  protocol::signature s;
  s.values.assign(256, 0.0f);
  s.values[9] = 1.0f;
  return s;
}

TEST(share_model, the_leaders_later_queries_carry_its_re_taken_model) {
  const auto queries = queries_of_a_leader(true, zoomed_signature());
  ASSERT_GE(queries.size(), 2u);
  EXPECT_EQ(queries.front().task.target, test_task().target) << "the first auction, at once";
  EXPECT_EQ(queries.back().task.target, zoomed_signature());
}

TEST(share_model, the_papers_leader_keeps_the_operators_signature) {
  const auto queries = queries_of_a_leader(false, zoomed_signature());
  ASSERT_GE(queries.size(), 2u);
  for (const auto& q : queries) EXPECT_EQ(q.task.target, test_task().target);
}

}  // namespace
}  // namespace argus::controller::testing
