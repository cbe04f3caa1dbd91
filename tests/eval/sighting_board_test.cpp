// sensing.group_geometry: ground_truth points a node where its group saw her in the last frame.
// Whom it is pointed at must not depend on which cameras have taken their turn of this tick.

#include "eval/sighting_board.hpp"

#include <gtest/gtest.h>

namespace argus::eval {
namespace {

TEST(sighting_board, the_leaders_box_comes_first_then_the_lowest_numbered_members) {
  sighting_board board;
  board.put(10, 0, 9, false, 41);
  board.put(10, 0, 4, false, 42);
  EXPECT_EQ(board.seen(10, 0, 0), 42);  // no leader's box: the lowest-numbered member's
  board.put(10, 0, 12, true, 43);
  EXPECT_EQ(board.seen(10, 0, 0), 43);             // the leader's
  EXPECT_EQ(board.seen(10, 0, 12), 42);            // but never the asking camera's own
  EXPECT_FALSE(board.seen(10, 1, 0).has_value());  // another task's group saw nobody
  EXPECT_FALSE(board.seen(9, 0, 0).has_value());   // nor did this group a frame earlier
}

TEST(sighting_board, what_a_node_reads_of_the_last_frame_stays_while_this_one_is_written) {
  sighting_board board;
  board.put(20, 3, 5, true, 7);
  // Tick 21: some cameras write their frame before others read the frame of tick 20.
  board.put(21, 3, 5, true, 8);
  board.put(21, 3, 6, false, 9);
  EXPECT_EQ(board.seen(20, 3, 1), 7);
  EXPECT_EQ(board.seen(21, 3, 1), 8);
  // Frames nobody can read any more go: at tick 23, the frame of 20.
  board.put(23, 3, 5, true, 10);
  EXPECT_FALSE(board.seen(20, 3, 1).has_value());
  EXPECT_EQ(board.seen(21, 3, 1), 8);
}

// The geometry points at whom another camera of the group holds; the reappearance at her, and
// only when no camera of the group (the asking one included) holds anyone.
TEST(sighting_board, a_node_is_aimed_at_whom_the_group_holds_or_at_her_when_it_holds_nobody) {
  constexpr int her = 77;
  sighting_board board;
  EXPECT_FALSE(board.aim(4, 0, 3, false, false, her).has_value());
  EXPECT_FALSE(board.aim(4, 0, 3, true, false, her).has_value());  // nobody held: no geometry
  EXPECT_EQ(board.aim(4, 0, 3, false, true, her), her);
  EXPECT_EQ(board.aim(4, 0, 3, true, true, her), her);
  board.put(5, 0, 8, true, 12);  // the leader holds a stranger
  EXPECT_EQ(board.aim(5, 0, 3, true, false, her), 12);
  EXPECT_EQ(board.aim(5, 0, 3, true, true, her), 12);
  EXPECT_FALSE(board.aim(5, 0, 3, false, true, her).has_value());  // the group holds someone
  // The asking camera's own hold is no one to point it at, but the group holds someone.
  EXPECT_FALSE(board.aim(5, 0, 8, true, true, her).has_value());
  EXPECT_FALSE(board.aim(5, 0, 8, false, false, her).has_value());
}

}  // namespace
}  // namespace argus::eval
