// A node's side of its links: hand-overs held until due, retracted by a cut, and a turn held
// until every hand-over the clock announced for it has come (docs/network.md).

#include "actors/net_arrivals.hpp"

#include <gtest/gtest.h>

namespace argus::actors {
namespace {

constexpr auto cameras = static_cast<std::uint8_t>(phase::cameras);

net_handover messages(std::initializer_list<std::int64_t> dues) {
  net_handover out;
  for (auto due : dues) {
    protocol::net_message m;
    m.id = static_cast<std::uint64_t>(due);
    out.add(due, std::move(m));
  }
  return out;
}

struct arrival {
  int from = 0;
  protocol::net_message message;
};

// Everything due before (`tick`, `phase`), in the order the node reads it.
std::vector<std::pair<mail_stamp, arrival>> take_due(net_arrivals& arrivals, std::int64_t tick,
                                                     std::uint8_t phase) {
  std::vector<std::pair<mail_stamp, arrival>> out;
  arrivals.for_each_due(tick, phase, [&](const mail_stamp& s, int from, protocol::net_message& m) {
    out.emplace_back(s, arrival{from, std::move(m)});
  });
  return out;
}

// A hand-over from link `link` answering its peer's flush in the turn (`tick`, cameras).
mail_stamp flushed(std::int64_t tick, std::uint64_t link) {
  return mail_stamp{tick, cameras, link, 0};
}

TEST(net_arrivals, a_turn_waits_for_every_announced_hand_over) {
  net_arrivals arrivals;
  arrivals.hold({12, cameras, caf::actor{}}, 2);
  EXPECT_FALSE(arrivals.take_ready());
  auto batch = messages({13, 14});
  arrivals.put(flushed(11, 100), true, 1, batch);
  EXPECT_FALSE(arrivals.take_ready());  // one of two
  auto empty = messages({});
  arrivals.put(flushed(11, 101), true, 2, empty);  // all lost on the way: still counts
  auto turn = arrivals.take_ready();
  ASSERT_TRUE(turn);
  EXPECT_EQ(turn->tick, 12);
  EXPECT_FALSE(arrivals.take_ready());  // taken once
}

TEST(net_arrivals, hand_overs_flushed_in_this_turn_or_unannounced_count_for_no_turn) {
  net_arrivals arrivals;
  // A peer in the same phase flushed at tick 12 before this node's turn at 12 ran: that
  // hand-over belongs to the next turn.
  auto same_turn = messages({13});
  arrivals.put(flushed(12, 100), true, 1, same_turn);
  // A crashed peer's last words, or what a recovered node is handed: nobody announced them.
  auto unannounced = messages({13});
  arrivals.put(flushed(11, 101), false, 2, unannounced);
  arrivals.hold({12, cameras, caf::actor{}}, 1);
  EXPECT_FALSE(arrivals.take_ready());
  auto late = messages({14});
  arrivals.put(flushed(11, 102), true, 3, late);
  ASSERT_TRUE(arrivals.take_ready());
  // The turn at 13 owes one announced hand-over: the one flushed at 12, already here.
  arrivals.hold({13, cameras, caf::actor{}}, 1);
  EXPECT_TRUE(arrivals.take_ready());
}

TEST(net_arrivals, messages_are_read_at_their_due_tick_in_canonical_order_unless_retracted) {
  net_arrivals arrivals;
  auto from_b = messages({5, 6, 9});
  arrivals.put(mail_stamp{2, cameras, 200, 40}, true, 2, from_b);
  auto from_a = messages({5, 9});
  arrivals.put(mail_stamp{2, cameras, 100, 7}, true, 1, from_a);
  auto due5 = take_due(arrivals, 5, cameras);
  ASSERT_EQ(due5.size(), 2u);
  EXPECT_EQ(due5[0].first.sender, 100u);  // by link, whatever the order they came in
  EXPECT_EQ(due5[0].first.seq, 7u);
  EXPECT_EQ(due5[1].first.sender, 200u);
  EXPECT_EQ(due5[1].first.seq, 40u);
  arrivals.retract(200, 7);  // link 200 was cut at 7: its message due at 9 never arrives
  auto rest = take_due(arrivals, 10, cameras);
  ASSERT_EQ(rest.size(), 2u);
  EXPECT_EQ(rest[0].second.from, 2);  // due 6, before the cut
  EXPECT_EQ(rest[0].first.tick, 6);
  EXPECT_EQ(rest[1].second.from, 1);
  EXPECT_EQ(rest[1].first.tick, 9);
}

TEST(net_arrivals, each_message_is_read_once_at_its_due_tick_whatever_order_it_came_in) {
  net_arrivals arrivals;
  // Reordered and duplicated mail: due ticks in no order within a hand-over.
  auto a = messages({9, 6, 12, 6});
  arrivals.put(mail_stamp{3, cameras, 100, 0}, true, 1, a);
  auto b = messages({7, 11});
  arrivals.put(mail_stamp{3, cameras, 200, 0}, true, 2, b);
  std::vector<std::int64_t> read;
  for (std::int64_t tick = 4; tick <= 13; ++tick) {
    for (const auto& [stamp, m] : take_due(arrivals, tick, cameras)) {
      EXPECT_EQ(stamp.tick, tick);  // not a tick late, not early
      read.push_back(static_cast<std::int64_t>(m.message.id));
    }
    if (tick == 8) arrivals.retract(200, 11);  // link 200 cut: its message due at 11 is gone
  }
  EXPECT_EQ(read, (std::vector<std::int64_t>{6, 6, 7, 9, 12}));
  EXPECT_EQ(arrivals.size(), 0u);
}

}  // namespace
}  // namespace argus::actors
