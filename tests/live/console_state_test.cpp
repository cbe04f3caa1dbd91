// What the console shows, built from the run's events as the recorder hands them over.
#include "live/console_state.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

namespace argus::live {
namespace {

config::scenario three_cameras() {
  config::scenario s;
  for (int id : {1, 2, 3}) {
    config::camera_settings c;
    c.id = id;
    s.cameras.push_back(c);
  }
  return s;
}

nlohmann::json camera(const nlohmann::json& state, int id) {
  for (const auto& c : state["cameras"])
    if (c["id"] == id) return c;
  return {};
}

TEST(console_state, follows_groups_states_and_crashes) {
  console_state console(three_cameras());
  const std::vector<event_line> events{
      {10, "script", "task_issued", R"("task":0,"by":"pixel","pixel":[1,2],"camera":2)"},
      {10, "camera/2", "task_target", R"("camera":2,"task":0,"pedestrian":12,"by":"pixel")"},
      {10, "camera/2", "task_created", R"("camera":2,"task":0,"min_cameras":1)"},
      {10, "camera/2", "node_state", R"("from":"idle","to":"performing_task")"},
      {12, "camera/3", "joined", R"("camera":3,"task":0,"leader":2,"reassign":false)"},
      {12, "camera/3", "tracking", R"("camera":3,"task":0,"state":"track")"},
  };
  console.record_events(events);
  auto state = console.state_json();
  ASSERT_EQ(state["groups"].size(), 1u);
  EXPECT_EQ(state["groups"][0]["task"], 0);
  EXPECT_EQ(state["groups"][0]["leader"], 2);
  EXPECT_EQ(state["groups"][0]["members"], nlohmann::json::array({2, 3}));
  EXPECT_EQ(camera(state, 2)["state"], "performing_task");
  EXPECT_EQ(camera(state, 3)["tracking"], "track");
  EXPECT_EQ(camera(state, 3)["task"], 0);
  ASSERT_EQ(state["tasks"].size(), 1u);
  EXPECT_EQ(state["tasks"][0]["pedestrian"], 12);
  EXPECT_EQ(state["tasks"][0]["status"], "observed");

  const std::vector<event_line> crash{
      {20, "faults", "fault", R"("fault":"crash","camera":2,"random":false,"applied":true)"},
      {20, "script", "task_cancelled", R"("task":0,"camera":2)"}};
  console.record_events(crash);
  state = console.state_json();
  EXPECT_EQ(camera(state, 2)["alive"], false);
  EXPECT_EQ(camera(state, 2)["state"], "crashed");
  EXPECT_EQ(state["groups"][0]["members"], nlohmann::json::array({3}));
  EXPECT_EQ(state["tasks"][0]["status"], "cancelled");
  EXPECT_FALSE(state["recent"].empty());

  console.record_events(
      std::vector<event_line>{{30, "faults", "node_recovered", R"("camera":2,"applied":true)"}});
  EXPECT_EQ(camera(console.state_json(), 2)["alive"], true);
}

TEST(console_state, feeds_only_what_a_node_sensed) {
  console_state console(three_cameras());
  EXPECT_FALSE(console.feed(1));
  console.publish_camera(1, 5, 10.0, -20.0, 40.0, cv::Mat(), {});
  EXPECT_FALSE(console.feed(1));  // it looked at nothing
  EXPECT_DOUBLE_EQ(console.pose(1)->pan_deg, 10.0);
  console.publish_camera(1, 6, 11.0, -20.0, 40.0, cv::Mat(4, 4, CV_8UC3, cv::Scalar(1, 2, 3)),
                         {cv::Rect2d(1, 1, 2, 2)});
  const auto frame = console.feed(1);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->tick, 6);
  EXPECT_EQ(frame->sequence, 1u);
  EXPECT_EQ(frame->boxes.size(), 1u);
  EXPECT_FALSE(console.feed(9));
  EXPECT_FALSE(console.pose(9));
}

TEST(console_state, a_workers_frame_arrives_as_jpeg_and_is_decoded_when_asked_for) {
  // argus serve --workers: a camera's frame crosses as JPEG and keeps its tick and boxes.
  console_state console(three_cameras());
  const cv::Mat sensed(24, 32, CV_8UC3, cv::Scalar(40, 90, 200));
  std::vector<unsigned char> jpeg;
  ASSERT_TRUE(cv::imencode(".jpg", sensed, jpeg));
  console.publish_camera_jpeg(2, 7, 12.0, -15.0, 30.0, jpeg, {cv::Rect2d(2, 3, 4, 5)});
  EXPECT_EQ(camera(console.state_json(), 2)["has_frame"], true);
  auto frame = console.feed(2);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->tick, 7);
  ASSERT_EQ(frame->image.size(), sensed.size());
  EXPECT_LT(cv::norm(frame->image, sensed, cv::NORM_INF), 8.0);  // JPEG's loss only
  ASSERT_EQ(frame->boxes.size(), 1u);
  EXPECT_EQ(frame->boxes[0], cv::Rect2d(2, 3, 4, 5));
  // A later turn that looked at nothing moves the camera and keeps its last frame.
  console.publish_camera_jpeg(2, 8, 13.0, -15.0, 30.0, {}, {});
  EXPECT_DOUBLE_EQ(console.pose(2)->pan_deg, 13.0);
  EXPECT_EQ(console.feed(2)->tick, 7);
  // Bytes that are no JPEG show no frame rather than a broken one.
  console.publish_camera_jpeg(3, 9, 0.0, 0.0, 30.0, {1, 2, 3}, {});
  EXPECT_FALSE(console.feed(3));
}

TEST(console_state, a_camera_is_watched_while_a_page_keeps_asking_for_its_feed) {
  console_state console(three_cameras());
  const auto t0 = std::chrono::steady_clock::time_point{} + std::chrono::hours(1);
  EXPECT_TRUE(console.watched(t0).empty());
  console.watch(3, t0);
  console.watch(1, t0 + std::chrono::milliseconds(1500));
  EXPECT_EQ(console.watched(t0 + std::chrono::seconds(1)), (std::vector<int>{1, 3}));
  // Two seconds after a page last asked, a camera is no longer watched.
  EXPECT_EQ(console.watched(t0 + std::chrono::milliseconds(2500)), (std::vector<int>{1}));
  EXPECT_TRUE(console.watched(t0 + std::chrono::seconds(4)).empty());
  console.watch(3, t0 + std::chrono::seconds(4));
  EXPECT_EQ(console.watched(t0 + std::chrono::seconds(5)), (std::vector<int>{3}));
}

}  // namespace
}  // namespace argus::live
