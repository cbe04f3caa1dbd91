#include "actors/ordered_inbox.hpp"

#include <gtest/gtest.h>

#include <string>

namespace argus::actors {
namespace {

TEST(ordered_inbox, releases_earlier_mail_in_canonical_order_whatever_the_arrival_order) {
  ordered_inbox<std::string> inbox;
  inbox.put({5, 2, 40, 1}, "d");
  inbox.put({5, 1, 90, 0}, "b");
  inbox.put({4, 3, 10, 7}, "a");
  inbox.put({5, 2, 40, 0}, "c");
  inbox.put({5, 3, 10, 8}, "same-phase");
  inbox.put({6, 0, 1, 0}, "future");
  auto due = inbox.take_due(5, 3);
  ASSERT_EQ(due.size(), 4u);
  EXPECT_EQ(due[0].second, "a");
  EXPECT_EQ(due[1].second, "b");
  EXPECT_EQ(due[2].second, "c");
  EXPECT_EQ(due[3].second, "d");
  // Mail of the receiver's own (tick, phase) and later waits for its next turn.
  EXPECT_EQ(inbox.size(), 2u);
  auto next = inbox.take_due(6, 3);
  ASSERT_EQ(next.size(), 2u);
  EXPECT_EQ(next[0].second, "same-phase");
  EXPECT_EQ(next[1].second, "future");
  EXPECT_EQ(inbox.size(), 0u);
}

}  // namespace
}  // namespace argus::actors
