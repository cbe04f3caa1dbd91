// The video recorder reads each camera's pose from the board in the same phase as the nodes
// write it: what it reads for tick t must not depend on whether the node has taken its turn of
// t yet.

#include "actors/camera_pose_board.hpp"

#include <gtest/gtest.h>

namespace argus::actors {
namespace {

const vision::ptz_state a{10.0, -20.0, 40.0};
const vision::ptz_state b{12.0, -19.0, 30.0};
const vision::ptz_state c{14.0, -18.0, 20.0};

TEST(camera_pose_board,
     reads_the_pose_written_before_the_tick_whether_or_not_the_node_wrote_in_it) {
  camera_pose_board board;
  EXPECT_FALSE(board.before(7, 0).has_value());  // before its first turn: the default pose
  board.put(7, 0, a);
  board.put(7, 1, b);
  // Tick 2, the recorder first: the pose of tick 1.
  ASSERT_TRUE(board.before(7, 2).has_value());
  EXPECT_EQ(board.before(7, 2)->pose, b);
  // Tick 2, the node first: still the pose of tick 1, not the one it has just moved to.
  board.put(7, 2, c);
  EXPECT_EQ(board.before(7, 2)->pose, b);
  EXPECT_EQ(board.before(7, 2)->tick, 1);
  EXPECT_EQ(board.before(7, 3)->pose, c);
  EXPECT_FALSE(board.before(8, 3).has_value());  // another camera's poses are its own
}

TEST(camera_pose_board, a_node_that_misses_turns_leaves_its_last_pose_with_its_tick) {
  camera_pose_board board;
  board.put(3, 4, a);
  board.put(3, 5, b);
  // Crashed after tick 5: at tick 9 the recorder sees the pose of tick 5, four ticks old.
  ASSERT_TRUE(board.before(3, 9).has_value());
  EXPECT_EQ(board.before(3, 9)->pose, b);
  EXPECT_EQ(board.before(3, 9)->tick, 5);
}

}  // namespace
}  // namespace argus::actors
