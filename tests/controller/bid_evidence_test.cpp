// A queried camera's bid (Fig. 13), with and without controller.bid_evidence_time: the paper's
// camera bids on its first find; with evidence, it keeps looking at what it found and bids only
// if that was found often enough, with a high enough mean acceptance score.

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "controller/camera_controller.hpp"
#include "protocol_harness.hpp"

namespace argus::controller::testing {
namespace {

// One queried camera (id 2) and the looks the test feeds it, frame by frame (ticks of 0.1 s).
struct bidder {
  explicit bidder(const config::scenario& s)
      : node(node_identity::from(s.cameras.front()), s), task(test_task(1, 2)) {}

  // Tick 0: leader 1's query. Then one look per tick: a score (found) or nothing (not found).
  // Returns the tick of the bid sent to 1, if any, and the reason the query was dropped.
  void run(const std::vector<std::optional<double>>& looks) {
    controller_input in;
    in.tick = 0;
    in.pose = node_identity::from(test_camera(2)).home;
    in.messages.push_back({1, protocol::query_relevance{task, 1, 1, 1, false}});
    record(node.step(in));
    for (std::size_t i = 0; i < looks.size(); ++i) {
      controller_input next;
      next.tick = static_cast<std::int64_t>(i) + 1;
      next.pose = in.pose;
      if (asked)
        next.looks.push_back(
            {task.task, looks[i].has_value(), centred_box(), looks[i].value_or(0), std::nullopt});
      record(node.step(next));
    }
  }

  void record(const controller_output& out) {
    asked = std::any_of(out.looks.begin(), out.looks.end(),
                        [this](const look_request& l) { return l.task == task.task; });
    for (const auto& m : out.messages)
      if (std::holds_alternative<protocol::relevance_bid>(m.message) && m.destination == 1 &&
          !bid_at)
        bid_at = tick;
    for (const auto& e : out.events)
      if (e.kind == "query_dropped") dropped = e.fields_json;
    ++tick;
  }

  camera_controller node;
  protocol::task_description task;
  bool asked = false;
  std::int64_t tick = 0;
  std::optional<std::int64_t> bid_at;
  std::string dropped;
};

config::scenario with_evidence(double seconds) {
  auto s = test_scenario({2});
  s.controller.bid_evidence_time = config::seconds{seconds};
  s.controller.bid_min_found_fraction = 0.6;
  s.controller.bid_min_mean_score = 0.5;
  return s;
}

TEST(bid_evidence, the_papers_camera_bids_on_its_first_find_whatever_its_score) {
  bidder b(test_scenario({2}));
  b.run({std::nullopt, 0.41, 0.41, 0.41});
  ASSERT_TRUE(b.bid_at.has_value());
  EXPECT_EQ(*b.bid_at, 2);  // the look of tick 2 (the second look) is the first find
}

TEST(bid_evidence, a_candidate_held_with_a_high_mean_score_gets_a_bid_after_the_window) {
  bidder b(with_evidence(1.0));
  std::vector<std::optional<double>> looks(3, std::nullopt);
  looks.resize(20, 0.6);
  b.run(looks);
  ASSERT_TRUE(b.bid_at.has_value()) << b.dropped;
  EXPECT_EQ(*b.bid_at, 4 + 10);  // first found at tick 4, then 1 s of looks
}

TEST(bid_evidence, a_first_find_that_scores_high_then_low_gets_no_bid) {
  // The first find is the best of everyone in view; the frames after it tell her apart.
  bidder b(with_evidence(1.0));
  std::vector<std::optional<double>> looks{0.8};
  looks.resize(20, 0.44);
  b.run(looks);
  EXPECT_FALSE(b.bid_at.has_value());
  EXPECT_NE(b.dropped.find("not_confirmed"), std::string::npos) << b.dropped;
}

TEST(bid_evidence, a_candidate_seen_in_too_few_frames_gets_no_bid) {
  bidder b(with_evidence(1.0));
  std::vector<std::optional<double>> looks;
  for (int i = 0; i < 20; ++i)
    looks.push_back(i % 3 == 0 ? std::optional<double>(0.7) : std::nullopt);
  b.run(looks);
  EXPECT_FALSE(b.bid_at.has_value());
  EXPECT_NE(b.dropped.find("not_confirmed"), std::string::npos) << b.dropped;
}

TEST(bid_evidence, nothing_found_within_the_look_time_is_not_found) {
  bidder b(with_evidence(1.0));
  b.run(std::vector<std::optional<double>>(20, std::nullopt));
  EXPECT_FALSE(b.bid_at.has_value());
  EXPECT_NE(b.dropped.find("\"not_found\""), std::string::npos) << b.dropped;
}

}  // namespace
}  // namespace argus::controller::testing
