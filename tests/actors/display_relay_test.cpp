// What a worker keeps of its cameras for a live run's console (actors/display_relay.hpp): every
// camera's pose, and frames (as JPEG, with the tracker's boxes) only for the cameras a page
// watches.

#include "actors/display_relay.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

namespace argus::actors {
namespace {

// The worker's own observer, which sees every turn whatever the console watches.
class counting_observer final : public node_observer {
 public:
  void traffic(int, std::uint64_t, std::uint64_t) override {}
  void picked(const task_pick&) override {}
  void turn_done(int, std::int64_t, const vision::ptz_state&, const cv::Mat&,
                 const std::vector<controller::look_result>&) override {
    ++turns;
  }
  int turns = 0;
};

const camera_display* shown(const live_display& display, int camera) {
  for (const auto& c : display.cameras)
    if (c.camera == camera) return &c;
  return nullptr;
}

TEST(display_relay, encodes_only_the_frames_of_the_cameras_a_page_watches) {
  auto inner = std::make_shared<counting_observer>();
  display_relay relay(inner);
  const cv::Mat frame(24, 32, CV_8UC3, cv::Scalar(10, 120, 200));
  controller::look_result found;
  found.found = true;
  found.box = cv::Rect2d(1, 2, 3, 4);
  vision::ptz_state pose;
  pose.pan_deg = 12.0;
  // No page watches at first: poses only.
  relay.turn_done(1, 5, pose, frame, {found});
  relay.turn_done(2, 5, pose, frame, {found});
  auto first = relay.take();
  ASSERT_EQ(first.cameras.size(), 2u);
  for (const auto& c : first.cameras) {
    EXPECT_TRUE(c.jpeg.empty()) << "camera " << c.camera;
    EXPECT_TRUE(c.boxes.empty()) << "camera " << c.camera;
    EXPECT_EQ(c.pose.pan_deg, 12.0);
  }
  relay.watch({2});
  relay.turn_done(1, 6, pose, frame, {found});
  relay.turn_done(2, 6, pose, frame, {found});
  auto second = relay.take();
  ASSERT_NE(shown(second, 1), nullptr);
  EXPECT_TRUE(shown(second, 1)->jpeg.empty());
  ASSERT_NE(shown(second, 2), nullptr);
  EXPECT_FALSE(shown(second, 2)->jpeg.empty());
  EXPECT_EQ(shown(second, 2)->boxes, (std::vector<double>{1, 2, 3, 4}));
  // The page moved on: camera 2's frames stop.
  relay.watch({});
  relay.turn_done(2, 7, pose, frame, {found});
  EXPECT_TRUE(shown(relay.take(), 2)->jpeg.empty());
  EXPECT_EQ(inner->turns, 5);
}

}  // namespace
}  // namespace argus::actors
