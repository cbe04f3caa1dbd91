// The grouping protocol (Section IV, Figs. 13 and 15) between camera controllers on an ideal
// network, frame by frame: auctions, joins, heartbeats, failures, hand-over and merging.

#include <gtest/gtest.h>

#include <algorithm>

#include "controller/csp_problem_builder.hpp"
#include "fmt/format.h"
#include "nlohmann/json.hpp"
#include "tests/controller/protocol_harness.hpp"
#include "tests/support/csp_log_check.hpp"

namespace argus::controller {
namespace {

using testing::centred_box;
using testing::poor_box;
using testing::protocol_harness;
using testing::test_scenario;
using testing::test_task;

// Cameras 1, 2 and 3. The operator tasks camera 1 with a target that 2 sees well and 3 poorly.
//
//   1 (leader) --queryrelevance--> 2, 3 --relevance--> 1 --join--> best free bidder
protocol_harness three_cameras(config::scenario s = test_scenario({1, 2, 3})) {
  protocol_harness h(std::move(s));
  h.sees = [](int camera, task_id, std::int64_t) -> std::optional<cv::Rect2d> {
    if (camera == 2) return centred_box();
    if (camera == 3) return poor_box();
    return centred_box();
  };
  h.operator_query_at(0, 1, test_task());
  return h;
}

TEST(group_protocol, an_operator_task_forms_a_group_of_the_best_bidders) {
  auto h = three_cameras();
  h.run_until(100);
  EXPECT_EQ(h.node(1).state(), node_state::performing_task);
  EXPECT_EQ(h.node(1).role(), group_role::leader);
  EXPECT_EQ(h.node(1).members(), std::vector<int>{2});
  EXPECT_EQ(h.node(2).state(), node_state::performing_task);
  EXPECT_EQ(h.node(2).leader(), 1);
  // 3 bid too, lost the auction and waits for a join until the bidding timeout (10 s here).
  EXPECT_EQ(h.node(3).state(), node_state::computing_relevance);
  EXPECT_EQ(h.count("bid", 3), 1u);
  h.run_until(130);
  EXPECT_EQ(h.node(3).state(), node_state::idle);
  EXPECT_EQ(h.count("task_created", 1), 1u);
  EXPECT_GE(h.count("auction", 1), 1u);
}

TEST(group_protocol, a_lost_bid_leaves_the_auction_to_the_others) {
  auto h = three_cameras();
  h.drop = [](int from, int, const protocol::group_message& m) {
    return from == 2 && std::holds_alternative<protocol::relevance_bid>(m);
  };
  h.run_until(60);
  EXPECT_EQ(h.node(1).members(), std::vector<int>{3});
  EXPECT_EQ(h.node(3).leader(), 1);
}

TEST(group_protocol, a_bidder_whose_join_was_lost_bids_again_in_the_next_auction) {
  // The join to camera 2 is lost. Its leader drops it as silent and auctions again; camera 2,
  // still waiting for a join (bidding timeout 10 s), must bid in the new auction rather than
  // stay deaf to the task until its timeout.
  auto h = three_cameras();
  bool lost = false;
  h.drop = [&lost](int, int to, const protocol::group_message& m) {
    if (lost || to != 2 || !std::holds_alternative<protocol::join>(m)) return false;
    lost = true;
    return true;
  };
  h.run_until(95);  // before camera 2's bidding timeout
  ASSERT_TRUE(lost);
  EXPECT_EQ(h.count("bid", 2), 2u);
  h.run_until(130);  // the second auction closes
  EXPECT_EQ(h.count("joined", 2), 1u);
  EXPECT_EQ(h.node(2).leader(), 1);
}

TEST(group_protocol, members_send_status_every_heartbeat) {
  auto h = three_cameras();
  h.run_until(100);
  const auto before = h.sent("status");
  h.run_until(200);  // 10 s: two nodes, one status each per second
  EXPECT_EQ(h.sent("status") - before, 20u);
}

TEST(group_protocol, a_silent_member_is_dropped_and_replaced) {
  auto h = three_cameras();
  h.run_until(100);
  ASSERT_EQ(h.node(1).members(), std::vector<int>{2});
  h.crash(2);
  h.run_until(160);  // member failure timeout 5 s
  EXPECT_EQ(h.count("member_dropped", 1), 1u);
  EXPECT_EQ(h.count("joined", 3), 0u);
  h.run_until(260);
  // Camera 3 was recruited in its place (it leaves again when its relevance decays, and says
  // so: its leader does not keep it as a ghost member).
  EXPECT_EQ(h.count("joined", 3), 1u);
}

TEST(group_protocol, a_member_takes_over_when_its_leader_falls_silent) {
  auto h = three_cameras();
  h.run_until(100);
  h.crash(1);
  h.run_until(125);  // leader failure timeout 3 s
  EXPECT_EQ(h.node(2).role(), group_role::leader);
  EXPECT_EQ(h.count("leader_changed", 2), 1u);
}

TEST(group_protocol, a_leader_that_loses_its_target_hands_the_group_over) {
  auto h = three_cameras();
  h.run_until(100);
  h.sees = [](int camera, task_id, std::int64_t) -> std::optional<cv::Rect2d> {
    if (camera == 1) return std::nullopt;
    return centred_box();
  };
  h.run_until(200);
  EXPECT_EQ(h.count("handoff", 1), 1u);
  EXPECT_EQ(h.node(2).role(), group_role::leader);
  // It left once it heard camera 2 lead.
  EXPECT_EQ(h.node(1).state(), node_state::idle);
  EXPECT_EQ(h.count("left_task", 1), 1u);
  // Its task over, the camera goes back to its default pose (Section III-C, reset).
  ASSERT_TRUE(h.last_command(1));
  EXPECT_EQ(*h.last_command(1), node_identity::from(testing::test_camera(1)).home);
}

// Fig. 10: a leader whose search failed leaves the task, head home; never a frozen head. Camera
// 1 loses her at 10 s; its member 2 still sees her until 13 s, when 1's search (1 s wait, 2 s
// search here) fails while 1's own relevance, decayed since 10 s, is still above the threshold
// (so the low-relevance hand-over does not apply). It hands the group to 2 and leaves.
TEST(group_protocol, a_leader_whose_search_failed_hands_over_and_goes_home) {
  auto s = test_scenario({1, 2, 3});
  s.controller.wait_timeout = config::seconds{1.0};
  s.controller.search_timeout = config::seconds{2.0};
  auto h = three_cameras(s);
  h.run_until(100);
  ASSERT_EQ(h.node(1).members(), std::vector<int>{2});
  h.sees = [](int camera, task_id, std::int64_t tick) -> std::optional<cv::Rect2d> {
    if (camera == 2 && tick < 150) return centred_box();
    return std::nullopt;
  };
  h.run_until(135);
  ASSERT_EQ(h.node(1).tracking(), vision::tracking_state::failed);
  h.run_until(137);
  EXPECT_EQ(h.count("handoff", 1), 1u);
  // Its head turns home at once, while it waits to hear camera 2 lead.
  ASSERT_TRUE(h.last_command(1));
  EXPECT_EQ(*h.last_command(1), node_identity::from(testing::test_camera(1)).home);
  h.run_until(160);
  EXPECT_EQ(h.node(2).role(), group_role::leader);
  EXPECT_EQ(h.node(1).state(), node_state::idle);
  ASSERT_TRUE(h.last_command(1));
  EXPECT_EQ(*h.last_command(1), node_identity::from(testing::test_camera(1)).home);
  // Camera 2, alone once its own search fails, ends the task: nobody holds a frozen head.
  h.run_until(200);
  EXPECT_EQ(h.node(2).state(), node_state::idle);
  EXPECT_EQ(h.count("group_vanished", 2), 1u);
}

// The member given the group crashes as the hand-over is sent (or the hand-over is lost and the
// member leaves): nobody would hold the task. The old leader, not heard from a new leader
// within the leader failure timeout, takes the group back and keeps looking.
TEST(group_protocol, a_hand_over_nobody_takes_up_is_taken_back) {
  auto h = three_cameras();
  h.run_until(100);
  ASSERT_EQ(h.node(1).members(), std::vector<int>{2});
  h.sees = [](int camera, task_id, std::int64_t) -> std::optional<cv::Rect2d> {
    if (camera == 2) return centred_box();
    return std::nullopt;
  };
  std::int64_t handed = -1;
  for (std::int64_t t = 101; t < 200 && handed < 0; ++t) {
    h.run_until(t);
    if (h.count("handoff", 1) == 1) handed = t;
  }
  ASSERT_GT(handed, 0) << "camera 1 never handed its group over";
  h.crash(2);
  EXPECT_EQ(h.node(1).state(), node_state::performing_task) << "it waits for the new leader";
  h.run_until(handed + 35);  // leader failure timeout 3 s
  EXPECT_EQ(h.node(1).state(), node_state::performing_task);
  EXPECT_EQ(h.node(1).role(), group_role::leader);
  EXPECT_EQ(h.count("left_task", 1), 0u);
  EXPECT_EQ(h.count("leader_changed", 1), 1u) << "it took the group back";
}

// Two leaders of one task (as after a leader's crash is wrongly presumed): the groups merge.
protocol_harness two_leaders(config::merge_rule rule) {
  auto s = test_scenario({1, 2, 3});
  s.controller.merge = rule;
  protocol_harness h(std::move(s));
  h.sees = [](int, task_id, std::int64_t) -> std::optional<cv::Rect2d> { return centred_box(); };
  h.operator_query_at(0, 1, test_task(1, 3));
  h.operator_query_at(0, 2, test_task(1, 3));
  return h;
}

// Who follows whom after the merge: the demoted leader and every member follow the one that
// stays, at its epoch, which is newer than either leadership's at the start (the merge started
// a new term).
void expect_one_group_under(protocol_harness& h, int winner, int loser) {
  EXPECT_EQ(h.leaders(7), std::set<int>{winner});
  EXPECT_EQ(h.node(loser).role(), group_role::member);
  EXPECT_EQ(h.node(loser).leader(), winner);
  EXPECT_GE(h.node(winner).term(), 2u);
  for (int id : {1, 2, 3}) {
    if (id == winner || !h.node(id).task()) continue;
    EXPECT_EQ(h.node(id).leader(), winner) << "camera " << id;
    EXPECT_EQ(h.node(id).term(), h.node(winner).term()) << "camera " << id;
  }
  // The one that stays never followed anyone: its only leader changes are its own new epochs.
  for (const auto& [camera, e] : h.events())
    if (camera == winner && e.kind == "leader_changed") {
      EXPECT_NE(e.fields_json.find("\"reason\":\"merged\""), std::string::npos) << e.fields_json;
      EXPECT_NE(e.fields_json.find(fmt::format("\"leader\":{},\"previous\":{}", winner, winner)),
                std::string::npos)
          << e.fields_json;
    }
  EXPECT_GE(h.count("leader_changed", winner), 1u) << "its new epoch is logged";
  EXPECT_GE(h.count("leader_changed", loser), 1u);
}

TEST(group_protocol, two_leaders_of_one_task_merge_under_the_highest_id) {
  auto h = two_leaders(config::merge_rule::highest_id);
  h.run_until(100);
  expect_one_group_under(h, 2, 1);
}

TEST(group_protocol, two_leaders_of_one_task_merge_by_negotiation) {
  auto h = two_leaders(config::merge_rule::negotiation);
  h.run_until(300);
  ASSERT_EQ(h.leaders(7).size(), 1u);
  EXPECT_GE(h.sent("demote"), 1u);
  EXPECT_GE(h.sent("demoteack"), 1u);
  // Fig. 15 Case 2(1): the leader that acknowledged its demotion follows the other.
  const int winner = *h.leaders(7).begin();
  expect_one_group_under(h, winner, 3 - winner);
  EXPECT_GE(h.count("demote", winner), 1u);
  EXPECT_EQ(h.count("demoteack", 3 - winner), 1u);
}

// Cameras 1 and 3 cannot hear each other; 2 hears both. Two leaders of one task, 1 and 3:
// 1 hears only 3's member 2, and merging by highest id makes it follow 3.
//
//   1 <--> 2 <--> 3      (1 and 3 out of each other's reach)
TEST(group_protocol, a_leader_merged_through_a_member_hears_its_new_leader_through_it) {
  auto s = test_scenario({1, 2, 3});
  protocol_harness h(std::move(s));
  h.sees = [](int, task_id, std::int64_t) -> std::optional<cv::Rect2d> { return centred_box(); };
  h.drop = [](int from, int to, const protocol::group_message&) {
    return (from == 1 && to == 3) || (from == 3 && to == 1);
  };
  h.operator_query_at(0, 3, test_task(1, 3));
  h.operator_query_at(20, 1, test_task(1, 3));
  h.run_until(600);  // a minute: twenty leader failure timeouts
  EXPECT_EQ(h.leaders(7), std::set<int>{3});
  EXPECT_EQ(h.node(1).leader(), 3);
  // Demoted once, and not taking the leader it cannot hear for failed every 3 s.
  EXPECT_LE(h.count("leader_changed", 1), 2u);
  EXPECT_EQ(h.count("leader_changed", 3), 0u);
}

// Fig. 15's two leaders can each accept the other's demote: camera 3 follows 16 at epoch 2,
// and 16's status says 16 now follows 3. Camera 3 must lead, at an epoch past 2 (argus chaos,
// penn_station seeds 540 and 690: it followed itself and took its ended epoch up again).
TEST(group_protocol, a_leader_whose_leader_follows_it_leads_at_a_new_epoch) {
  const auto s = test_scenario({3});
  camera_controller node(node_identity::from(s.cameras.front()), s);
  const auto task = test_task(1, 4);
  std::int64_t tick = 0;
  const auto step = [&](std::vector<received_message> messages) {
    controller_input in;
    in.tick = tick++;
    in.pose = node_identity::from(s.cameras.front()).home;
    in.messages = std::move(messages);
    return node.step(in);
  };
  step({{16, protocol::join{task, 16, 2, 3, false}}});
  ASSERT_EQ(node.leader(), 16);
  ASSERT_EQ(node.term(), 2u);
  step({{16, protocol::status{task.task, 16, 3, 2, 0.9, 1, 4, {}, false}}});
  EXPECT_EQ(node.role(), group_role::leader);
  EXPECT_EQ(node.leader(), 3);
  EXPECT_GT(node.term(), 2u);
}

// Camera 3 follows leader 16 and relays for camera 9, which 16's last status did not list (out
// of 16's reach, as far as 3 can tell). 16's own statuses go on to 9; a copy of one that another
// member relayed must not: in seed 6 of penn_station (with the re-taken model) members 3, 4
// and 9 of 16's group each relayed for the other two, so each of 16's statuses went round
// them for good, a new one joining every heartbeat, until the run held 24 GB at 690 s.
TEST(group_protocol, a_member_relays_first_hand_statuses_only) {
  const auto s = test_scenario({3});
  camera_controller member(node_identity::from(s.cameras.front()), s);
  const auto task = test_task(1, 4);
  // How many messages of kind T this step sent to `to`.
  const auto sent = []<typename T>(const controller_output& out, int to) {
    return std::count_if(out.messages.begin(), out.messages.end(), [to](const auto& m) {
      return m.destination == to && std::holds_alternative<T>(m.message);
    });
  };
  const auto statuses_to = [&sent](const controller_output& out, int to) {
    return sent.template operator()<protocol::status>(out, to);
  };
  const auto leader_status = [&task](std::vector<int> members) {
    return protocol::status{task.task, 16, 16, 1, 0.9, 1, 4, std::move(members), false};
  };
  std::int64_t tick = 0;
  const auto step = [&](std::vector<received_message> messages) {
    controller_input in;
    in.tick = tick++;
    in.pose = node_identity::from(s.cameras.front()).home;
    in.messages = std::move(messages);
    return member.step(in);
  };
  step({{16, protocol::join{task, 16, 1, 3, false}}});
  ASSERT_EQ(member.leader(), 16);
  step({{16, leader_status({3})}});
  // 9 follows 16 but is not on its list: 3 relays for it, its status up to 16...
  const auto up = step({{9, protocol::status{task.task, 9, 16, 1, 0.7, 1, 4, {}, false}}});
  EXPECT_EQ(statuses_to(up, 16), 1);
  // ...and 16's own statuses down to it.
  EXPECT_EQ(statuses_to(step({{16, leader_status({3})}}), 9), 1);
  // A copy of 16's status that member 4 relayed goes no further: not to 9, not back to 4.
  const auto relayed = step({{4, leader_status({3})}});
  EXPECT_EQ(statuses_to(relayed, 9), 0);
  EXPECT_EQ(statuses_to(relayed, 4), 0);
  EXPECT_EQ(member.leader(), 16);
  // Nor does a copy of 9's status that another member relayed go up again.
  EXPECT_EQ(
      statuses_to(step({{4, protocol::status{task.task, 9, 16, 1, 0.7, 1, 4, {}, false}}}), 16), 0);
  // Bids likewise: a bidder's own bid goes up to the leader, a relayed copy does not.
  const protocol::relevance_bid bid{task.task, 16, 1, 1, 5, 0.6, false, false, std::nullopt, 0};
  EXPECT_EQ(sent.template operator()<protocol::relevance_bid>(step({{5, bid}}), 16), 1);
  EXPECT_EQ(sent.template operator()<protocol::relevance_bid>(step({{4, bid}}), 16), 0);
  // And joins: the leader's own copy goes on to the invitee, a copy from anyone else does not.
  const protocol::join join{task, 16, 1, 5, false};
  EXPECT_EQ(sent.template operator()<protocol::join>(step({{16, join}}), 5), 1);
  EXPECT_EQ(sent.template operator()<protocol::join>(step({{4, join}}), 5), 0);
}

// Camera 3 (the highest id) leads 1 and 2, loses its target and hands the group to one of them.
// A status the new leader sent as 3's member, still on its way, reaches the other after the
// hand-over: it names 3 as leader and must not send the other back to the leader that left (by
// highest id 3 would then win every merge, and the group would follow a leader that is gone).
TEST(group_protocol, statuses_naming_a_leader_that_handed_over_do_not_bring_it_back) {
  for (std::int64_t delay : {3, 5, 8, 12}) {
    SCOPED_TRACE(delay);
    protocol_harness h(test_scenario({1, 2, 3}), delay);
    h.sees = [](int, task_id, std::int64_t) -> std::optional<cv::Rect2d> { return centred_box(); };
    h.operator_query_at(0, 3, test_task(3, 3));
    h.run_until(100);
    ASSERT_EQ(h.node(3).members(), (std::vector<int>{1, 2}));
    h.sees = [](int camera, task_id, std::int64_t) -> std::optional<cv::Rect2d> {
      if (camera == 3) return std::nullopt;
      return centred_box();
    };
    h.run_until(600);
    EXPECT_EQ(h.count("handoff", 3), 1u);
    const auto leaders = h.leaders(7);
    ASSERT_EQ(leaders.size(), 1u);
    const int leader = *leaders.begin();
    EXPECT_NE(leader, 3);
    EXPECT_EQ(h.node(3 - leader).leader(), leader);  // the other of 1 and 2
    EXPECT_LE(h.count("leader_changed", 1) + h.count("leader_changed", 2), 3u);
  }
}

// Camera 2 serves task 7 with leader 1 when task 8 arrives at camera 3, wanting two cameras;
// 2 is the only other camera that sees 8's target. Camera 1 sees 7's target only.
protocol_harness contested(config::scenario s) {
  protocol_harness h(std::move(s));
  h.sees = [](int camera, task_id task, std::int64_t) -> std::optional<cv::Rect2d> {
    if (camera == 2) return centred_box();
    if (camera == 3 && task == 8) return centred_box();
    if (camera == 1 && task == 7) return centred_box();
    return std::nullopt;
  };
  h.operator_query_at(0, 1, test_task(2, 2));
  auto other = test_task(2, 2);
  other.task = 8;
  h.operator_query_at(100, 3, other);
  return h;
}

void expect_optimal(const std::string& fields) {
  argus::testing::expect_optimal(nlohmann::json::parse("{" + fields + "}"));
}

// Camera 2, busy in task 7, hears task 8's query for itself and initiates conflict resolution
// (Section IV-B); leader 1 (the lower task) centralises it. Each group needs 2, and three
// cameras can serve: the minima are relaxed (csp.hpp's rule 2: task 8, the higher index, goes
// to 1), and the optimum keeps 2 with task 7.
TEST(group_protocol, a_busy_camera_queried_by_another_group_starts_conflict_resolution) {
  auto h = contested(test_scenario({1, 2, 3}));
  auto told = std::make_shared<std::vector<protocol::csp_data>>();
  auto bids = std::make_shared<std::vector<protocol::relevance_bid>>();
  h.drop = [told, bids](int from, int to, const protocol::group_message& m) {
    if (const auto* d = std::get_if<protocol::csp_data>(&m); d && to == 1) told->push_back(*d);
    if (const auto* b = std::get_if<protocol::relevance_bid>(&m); b && from == 2 && b->busy)
      bids->push_back(*b);
    return false;
  };
  h.run_until(300);
  EXPECT_GE(h.count("conflict_reported", 2), 1u);
  EXPECT_GE(h.sent("cspconflict"), 1u);
  EXPECT_GE(h.count("conflict", 1), 1u);
  EXPECT_EQ(h.count("conflict", 3), 0u);
  ASSERT_FALSE(told->empty());
  ASSERT_FALSE(bids->empty());
  std::size_t rounds = 0;
  for (const auto& [camera, e] : h.events()) {
    if (e.kind != "csp_solved") continue;
    ++rounds;
    EXPECT_EQ(camera, 1);
    expect_optimal(e.fields_json);
    const auto j = nlohmann::json::parse("{" + e.fields_json + "}");
    const auto logged = argus::testing::read_csp(j);
    // What leader 3 said of itself and of camera 2 is what the solver weighed.
    for (const auto& c : told->front().candidates) {
      auto at = std::find(logged.camera_ids.begin(), logged.camera_ids.end(), c.camera);
      if (at == logged.camera_ids.end()) continue;
      EXPECT_NEAR(j["relevance"][1][at - logged.camera_ids.begin()].get<double>(), c.relevance,
                  1e-6);
    }
    EXPECT_NE(e.fields_json.find("\"relaxed\":true"), std::string::npos);
    EXPECT_NE(e.fields_json.find("\"minima\":{\"7\":2,\"8\":1}"), std::string::npos);
  }
  // Settled once: the same conflict is not settled again within the minimum task duration.
  EXPECT_EQ(rounds, 1u);
  EXPECT_EQ(h.node(2).task(), 7u);
  EXPECT_EQ(h.node(1).members(), std::vector<int>{2});
  EXPECT_EQ(h.node(3).role(), group_role::leader);
  EXPECT_TRUE(h.node(3).members().empty());
}

// Fig. 19 frame by frame: camera 1 leads task 7 and camera 2 task 8, each seeing its own target
// poorly and the other's well. They decide between them: the CSP, leaders included, swaps them.
TEST(group_protocol, two_leaders_decide_between_them_which_carries_which_task) {
  protocol_harness h(test_scenario({1, 2}));
  h.sees = [](int camera, task_id task, std::int64_t) -> std::optional<cv::Rect2d> {
    const bool own = (camera == 1) == (task == 7);
    return own ? poor_box() : centred_box();
  };
  h.operator_query_at(0, 1, test_task(1, 1), poor_box());
  auto other = test_task(1, 1);
  other.task = 8;
  h.operator_query_at(0, 2, other, poor_box());
  h.run_until(400);
  ASSERT_GE(h.count("csp_solved"), 1u);
  for (const auto& [camera, e] : h.events())
    if (e.kind == "csp_solved") expect_optimal(e.fields_json);
  EXPECT_EQ(h.node(1).task(), 8u);
  EXPECT_EQ(h.node(2).task(), 7u);
  EXPECT_EQ(h.node(1).role(), group_role::leader);
  EXPECT_EQ(h.node(2).role(), group_role::leader);
  // New leaderships, at new epochs, logged as such.
  EXPECT_EQ(h.count("leader_changed", 1), 1u);
  EXPECT_EQ(h.count("leader_changed", 2), 1u);
  EXPECT_GE(h.node(1).term(), 2u);
  EXPECT_GE(h.node(2).term(), 2u);
  EXPECT_EQ(h.leaders(7), std::set<int>{2});
  EXPECT_EQ(h.leaders(8), std::set<int>{1});
}

// A lost result must not end a task: camera 2 misses the result camera 1 (task 7's leader)
// solved and stays where it was, leading task 8, until camera 1, which took the result, hears it
// there and tells it again.
TEST(group_protocol, a_lost_conflict_result_leaves_every_task_led) {
  {
    const int deaf = 2;
    protocol_harness h(test_scenario({1, 2}));
    h.sees = [](int camera, task_id task, std::int64_t) -> std::optional<cv::Rect2d> {
      const bool own = (camera == 1) == (task == 7);
      return own ? poor_box() : centred_box();
    };
    auto lost = std::make_shared<int>(0);
    h.drop = [deaf, lost](int, int to, const protocol::group_message& m) {
      return to == deaf && std::holds_alternative<protocol::csp_result>(m) && (*lost)++ == 0;
    };
    h.operator_query_at(0, 1, test_task(1, 1), poor_box());
    auto other = test_task(1, 1);
    other.task = 8;
    h.operator_query_at(0, 2, other, poor_box());
    h.run_until(600);
    EXPECT_GE(*lost, 2);  // the first copy lost, a second taken
    EXPECT_EQ(h.count("csp_solved", 1), 1u);
    EXPECT_EQ(h.leaders(7), std::set<int>{2});
    EXPECT_EQ(h.leaders(8), std::set<int>{1});
  }
}

}  // namespace
}  // namespace argus::controller
