#include "report/camera_logs.hpp"

#include <gtest/gtest.h>

#include <string>

namespace argus::report {
namespace {

const char* const poses_csv =
    "tick,t,camera,pan,tilt,fov,state\n"
    "1,0.066667,1,36.000,-20.000,45.000,idle\n"
    "1,0.066667,3,-144.000,-20.000,45.000,idle\n"
    "90,6.000000,1,40.500,-18.000,30.000,performing_task\n"
    "151,10.066667,3,-144.000,-20.000,45.000,down\n";

TEST(camera_logs, a_cameras_pose_holds_from_its_row_to_the_next) {
  const auto poses = pose_history::parse(poses_csv, "poses.csv");
  EXPECT_EQ(poses.at(1, 0), nullptr);  // before its first row: the scenario's pose
  ASSERT_NE(poses.at(1, 1), nullptr);
  EXPECT_DOUBLE_EQ(poses.at(1, 89)->pan_deg, 36.0);
  EXPECT_DOUBLE_EQ(poses.at(1, 90)->pan_deg, 40.5);
  EXPECT_DOUBLE_EQ(poses.at(1, 5000)->field_of_view_deg, 30.0);
  EXPECT_EQ(poses.at(3, 150)->state, "idle");
  EXPECT_EQ(poses.at(3, 151)->state, "down");
  EXPECT_EQ(poses.at(2, 100), nullptr);
  EXPECT_EQ(poses.cameras(), (std::vector<int>{1, 3}));
  ASSERT_EQ(poses.rows_of(1).size(), 2u);
  EXPECT_EQ(poses.rows_of(1)[1].world_tick, 90);
  EXPECT_TRUE(poses.rows_of(2).empty());
}

TEST(camera_logs, tracks_by_camera_and_tick_and_the_first_report_on_a_task) {
  const auto tracks = track_history::parse(
      "tick,t,camera,task,role,found,x,y,w,h,score,truth,iou,observed\r\n"
      "242,16.133333,7,0,leader,1,3.0,67.0,11.0,31.0,0.5959,84,0.5346,1\r\n"
      "243,16.200000,7,0,leader,0,0.0,0.0,0.0,0.0,0.0000,-1,0.0000,0\r\n"
      "244,16.266667,7,0,leader,1,161.0,116.0,9.0,25.0,0.4051,52,0.0000,0\r\n",
      "tracks.csv");
  const auto at = tracks.at(7, 242);
  ASSERT_EQ(at.size(), 1u);
  EXPECT_TRUE(at[0].found);
  EXPECT_TRUE(at[0].observed);
  EXPECT_DOUBLE_EQ(at[0].x, 3.0);
  EXPECT_DOUBLE_EQ(at[0].height, 31.0);
  EXPECT_FALSE(tracks.at(7, 243)[0].found);
  EXPECT_FALSE(tracks.at(7, 244)[0].observed);
  EXPECT_TRUE(tracks.at(6, 242).empty());
  EXPECT_EQ(tracks.first_report(7, 0, 241, 248), 242);
  EXPECT_EQ(tracks.first_report(7, 0, 243, 248), 243);
  EXPECT_EQ(tracks.first_report(7, 1, 241, 248), -1);
  EXPECT_EQ(tracks.first_report(7, 0, 230, 240), -1);
}

// The message of the error parsing `text` throws.
std::string error_of(const std::string& text, bool poses) {
  try {
    if (poses)
      pose_history::parse(text, "run/poses.csv");
    else
      track_history::parse(text, "run/tracks.csv");
  } catch (const camera_log_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(camera_logs, a_bad_file_is_named_with_its_line) {
  EXPECT_EQ(
      error_of("tick,t,camera,pan,tilt,fov,state\n1,0.1,1,36,-20,45,idle\n2,0.2,1,36\n", true),
      "run/poses.csv:3: expected 7 fields, got 4");
  EXPECT_EQ(error_of("tick,t,camera,pan,tilt,fov,state\n1,0.1,1,east,-20,45,idle\n", true),
            "run/poses.csv:2: column pan: expected a number, got 'east'");
  EXPECT_EQ(error_of("tick,t,camera,pan,tilt,state\n", true),
            "run/poses.csv:1: no column 'fov' in the header 'tick,t,camera,pan,tilt,state'");
  EXPECT_EQ(error_of("", true), "run/poses.csv: empty, expected a header line");
  EXPECT_EQ(error_of("tick,t,camera,pan,tilt,fov,state\n9,0.6,1,36,-20,45,idle\n"
                     "3,0.2,1,36,-20,45,idle\n",
                     true),
            "run/poses.csv:3: tick 3 comes after tick 9 of the same camera");
  EXPECT_EQ(error_of("tick,t,camera,task,role,found,x,y,w,h,score,truth,iou,observed\n"
                     "2.5,0.1,7,0,leader,1,3,67,11,31,0.5,84,0.5,1\n",
                     false),
            "run/tracks.csv:2: column tick: expected a whole number, got '2.5'");
  EXPECT_EQ(error_of("tick,t,camera,task,role,found,x,y,w,h,score,truth,iou,observed\n"
                     "1e300,0.1,7,0,leader,1,3,67,11,31,0.5,84,0.5,1\n",
                     false),
            "run/tracks.csv:2: column tick: expected a whole number, got '1e300'");
}

TEST(camera_logs, a_missing_file_is_named) {
  try {
    pose_history::read("/nonexistent/run/poses.csv");
    FAIL() << "no error";
  } catch (const camera_log_error& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/run/poses.csv: cannot be read");
  }
}

}  // namespace
}  // namespace argus::report
