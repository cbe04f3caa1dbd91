// Fig. 15, case by case, on one leader's negotiator.

#include "controller/demotion_negotiator.hpp"

#include <gtest/gtest.h>

#include <set>

namespace argus::controller {
namespace {

using protocol::demotion_step;
using step_list = std::vector<std::pair<int, demotion_step>>;

// No back-off (interval 0), so a demote scheduled at tick t goes out at tick t.
demotion_negotiator immediate() {
  return demotion_negotiator(1000, 0, 1);
}

TEST(demotion_negotiator, case_1_meeting_a_leader_sends_demote_after_the_interval) {
  demotion_negotiator n(1000, 10, 42);
  n.met_leader(5, 100);
  demotion_negotiator::actions a;
  std::int64_t sent_at = -1;
  for (std::int64_t t = 100; t <= 111 && sent_at < 0; ++t) {
    n.tick(t, a);
    if (!a.sends.empty()) sent_at = t;
  }
  ASSERT_GE(sent_at, 100);
  EXPECT_LE(sent_at, 110);
  EXPECT_EQ(a.sends, (step_list{{5, demotion_step::demote}}));
}

TEST(demotion_negotiator, case_1_only_when_not_negotiating_with_another_node) {
  auto n = immediate();
  n.met_leader(5, 0);
  n.met_leader(6, 0);
  demotion_negotiator::actions a;
  n.tick(0, a);
  EXPECT_EQ(a.sends, (step_list{{5, demotion_step::demote}}));
}

TEST(demotion_negotiator, case_2_1_demote_without_having_sent_one_demotes_this_leader) {
  auto n = immediate();
  demotion_negotiator::actions a;
  n.receive(5, demotion_step::demote, 0, a);
  EXPECT_EQ(a.sends, (step_list{{5, demotion_step::ack}}));
  EXPECT_EQ(a.demoted_to, 5);
  EXPECT_FALSE(n.negotiating());
}

TEST(demotion_negotiator, case_2_2_crossing_demotes_are_retried) {
  auto n = immediate();
  n.met_leader(5, 0);
  demotion_negotiator::actions a;
  n.tick(0, a);  // demote to 5
  demotion_negotiator::actions b;
  n.receive(5, demotion_step::demote, 1, b);
  EXPECT_EQ(b.sends, (step_list{{5, demotion_step::retry}}));
  EXPECT_FALSE(b.demoted_to);
  demotion_negotiator::actions c;
  n.tick(1, c);  // and a demote again after the (zero) interval
  EXPECT_EQ(c.sends, (step_list{{5, demotion_step::demote}}));
}

TEST(demotion_negotiator, case_2_3_demote_while_negotiating_with_another_is_refused) {
  auto n = immediate();
  n.met_leader(5, 0);
  demotion_negotiator::actions a;
  n.tick(0, a);
  demotion_negotiator::actions b;
  n.receive(6, demotion_step::demote, 1, b);
  EXPECT_EQ(b.sends, (step_list{{6, demotion_step::nack}}));
  EXPECT_FALSE(b.demoted_to);
}

TEST(demotion_negotiator, case_3_a_nack_ends_the_negotiation) {
  auto n = immediate();
  n.met_leader(5, 0);
  demotion_negotiator::actions a;
  n.tick(0, a);
  n.receive(5, demotion_step::nack, 1, a);
  EXPECT_FALSE(n.negotiating());
}

TEST(demotion_negotiator, case_4_an_ack_absorbs_the_demoted_leader) {
  auto n = immediate();
  n.met_leader(5, 0);
  demotion_negotiator::actions a;
  n.tick(0, a);
  demotion_negotiator::actions b;
  n.receive(5, demotion_step::ack, 1, b);
  EXPECT_EQ(b.absorbed, std::vector<int>{5});
  EXPECT_FALSE(n.negotiating());
}

TEST(demotion_negotiator, case_5_a_retry_schedules_another_demote) {
  auto n = immediate();
  demotion_negotiator::actions a;
  n.receive(5, demotion_step::retry, 3, a);
  EXPECT_TRUE(a.sends.empty());
  n.tick(3, a);
  EXPECT_EQ(a.sends, (step_list{{5, demotion_step::demote}}));
}

TEST(demotion_negotiator, an_unanswered_negotiation_ends_at_the_merge_timeout) {
  demotion_negotiator n(50, 0, 1);
  n.met_leader(5, 0);
  demotion_negotiator::actions a;
  for (std::int64_t t = 0; t < 50; ++t) n.tick(t, a);
  EXPECT_TRUE(n.negotiating());
  n.tick(50, a);
  EXPECT_FALSE(n.negotiating());
}

TEST(demotion_negotiator, the_interval_comes_from_the_seeded_stream) {
  auto first_send = [](std::uint64_t seed) {
    demotion_negotiator n(1000, 1000, seed);
    n.met_leader(5, 0);
    for (std::int64_t t = 0; t <= 1000; ++t) {
      demotion_negotiator::actions a;
      n.tick(t, a);
      if (!a.sends.empty()) return t;
    }
    return std::int64_t{-1};
  };
  EXPECT_EQ(first_send(7), first_send(7));
  std::set<std::int64_t> seen;
  for (std::uint64_t s = 1; s <= 8; ++s) seen.insert(first_send(s));
  EXPECT_GT(seen.size(), 4u);
}

}  // namespace
}  // namespace argus::controller
