// sensing.group_geometry: calibrated aims and gates a node by its group's latest floor estimate
// of her. What a node reads must not depend on which cameras have taken their turn of this tick.

#include "eval/position_board.hpp"

#include <gtest/gtest.h>

namespace argus::eval {
namespace {

vision::floor_estimate at(double x, std::int64_t tick) {
  return {{x, 0.0}, 0.5, tick};
}

TEST(position_board, the_latest_frame_counts_the_leaders_estimate_first) {
  position_board board;
  EXPECT_FALSE(board.latest(0, 100).has_value());
  board.put(0, 9, false, at(1.0, 10));
  board.put(0, 4, false, at(2.0, 10));
  EXPECT_EQ(board.latest(0, 10)->where.x(), 2.0);  // no leader's: the lowest-numbered member's
  board.put(0, 12, true, at(3.0, 10));
  EXPECT_EQ(board.latest(0, 10)->where.x(), 3.0);
  EXPECT_FALSE(board.latest(1, 10).has_value());  // another task's group has none
  // A frame with no estimate keeps the last one, with its own tick: its age is the reader's.
  EXPECT_EQ(board.latest(0, 30)->tick, 10);
  board.put(0, 9, false, at(4.0, 31));
  EXPECT_EQ(board.latest(0, 31)->where.x(), 4.0);  // a member's, newer than the leader's
}

TEST(position_board, what_a_node_reads_of_earlier_frames_stays_while_this_one_is_written) {
  position_board board;
  board.put(3, 5, true, at(1.0, 20));
  // Tick 21: some cameras write their frame before others read up to tick 20.
  board.put(3, 6, false, at(2.0, 21));
  EXPECT_EQ(board.latest(3, 20)->where.x(), 1.0);
  EXPECT_EQ(board.latest(3, 21)->where.x(), 2.0);
  // Frames older than anyone trusts go.
  board.put(3, 5, true, at(5.0, 21 + position_board::kept_ticks + 1));
  EXPECT_FALSE(board.latest(3, 21).has_value());
}

}  // namespace
}  // namespace argus::eval
