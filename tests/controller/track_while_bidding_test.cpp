// A queried camera's head while it bids (Fig. 10: the child FSM is embedded in
// ComputingRelevance too), with and without controller.track_while_bidding: the paper-as-first-
// built camera holds its pose and stops looking once it has bid; with the option it fixates and
// zooms on what it found, keeps following it until the join could have come, and joins with
// her in view.

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "controller/camera_controller.hpp"
#include "protocol_harness.hpp"

namespace argus::controller::testing {
namespace {

// One queried camera (id 2), its head moved at once to whatever it commands. Every look finds
// the target: at poor_box() (off-centre, small) from the home pose, centred and large once the
// head has turned to her.
struct follower {
  explicit follower(bool track_while_bidding)
      : settings([&] {
          auto s = test_scenario({2});
          s.controller.track_while_bidding = track_while_bidding;
          return s;
        }()),
        node(node_identity::from(settings.cameras.front()), settings),
        task(test_task(1, 2)),
        home(node_identity::from(settings.cameras.front()).home),
        pose(home) {}

  // The frame of tick `tick`, with leader 1's messages of that tick.
  controller_output step(std::vector<received_message> messages = {}) {
    controller_input in;
    in.tick = tick++;
    in.pose = pose;
    in.messages = std::move(messages);
    const auto box = pose == home ? poor_box() : centred_box();
    if (asked) in.looks.push_back({task.task, true, box, 0.6, std::nullopt});
    auto out = node.step(in);
    asked = std::any_of(out.looks.begin(), out.looks.end(),
                        [this](const look_request& l) { return l.task == task.task; });
    if (out.command) pose = *out.command;
    for (const auto& m : out.messages)
      if (const auto* b = std::get_if<protocol::relevance_bid>(&m.message)) bid = *b;
    return out;
  }

  void query() { step({{1, protocol::query_relevance{task, 1, 1, 1, false}}}); }
  void join() { step({{1, protocol::join{task, 1, 1, 2, false}}}); }

  config::scenario settings;
  camera_controller node;
  protocol::task_description task;
  vision::ptz_state home;
  vision::ptz_state pose;
  std::int64_t tick = 0;
  bool asked = false;
  std::optional<protocol::relevance_bid> bid;
};

TEST(track_while_bidding, the_first_built_bidder_holds_its_pose_and_stops_looking_once_it_bids) {
  follower f(false);
  const auto home = f.pose;
  f.query();
  for (int i = 0; i < 5; ++i) f.step();
  ASSERT_TRUE(f.bid.has_value());
  EXPECT_EQ(f.pose, home);
  EXPECT_FALSE(f.asked);
}

TEST(track_while_bidding, a_bidder_fixates_and_zooms_on_its_find_until_the_join_could_have_come) {
  follower f(true);
  const auto home = f.pose;
  f.query();
  for (int i = 0; i < 5; ++i) f.step();
  ASSERT_TRUE(f.bid.has_value());
  EXPECT_TRUE(f.asked);                     // still looking after its bid
  EXPECT_LT(f.pose.pan_deg, home.pan_deg);  // turned towards the box on the right
  EXPECT_LT(f.pose.field_of_view_deg, home.field_of_view_deg);  // zoomed on a small box
  // No join within the auction window (3 s) and a message timeout (1.5 s): back home, no look.
  for (int i = 0; i < 50; ++i) f.step();
  EXPECT_FALSE(f.asked);
  EXPECT_EQ(f.pose, home);
}

TEST(track_while_bidding, a_bidder_that_followed_its_find_joins_with_it_fresh_and_in_track) {
  // Both join 3 s after their bid; the first-built one joins with the relevance of its find
  // decayed over those 3 s (footnote 2), the follower with what it saw in its last frame.
  double joined_relevance[2] = {0.0, 0.0};
  for (bool option : {false, true}) {
    follower f(option);
    f.query();
    f.step();
    ASSERT_TRUE(f.bid.has_value());
    for (int i = 0; i < 30; ++i) f.step();
    f.join();
    ASSERT_EQ(f.node.state(), node_state::performing_task);
    EXPECT_EQ(f.node.tracking(), vision::tracking_state::track);
    joined_relevance[option ? 1 : 0] = f.node.relevance(f.tick - 1);
  }
  EXPECT_GT(joined_relevance[1], 2.0 * joined_relevance[0]);
}

}  // namespace
}  // namespace argus::controller::testing
