#include "vision/tracker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "opencv2/imgproc.hpp"
#include "tests/vision/static_camera.hpp"

namespace argus::vision {
namespace {

double overlap(const cv::Rect& a, const cv::Rect& b) {
  double shared = (a & b).area();
  return shared / (a.area() + b.area() - shared);
}

cv::Mat background(unsigned seed) {
  cv::Mat image(240, 320, CV_8UC3);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> shade(60, 170);
  for (int y = 0; y < 240; y += 8)
    for (int x = 0; x < 320; x += 8) {
      int g = shade(rng);
      cv::rectangle(image, cv::Rect(x, y, 8, 8), cv::Scalar(g - 20, g, g + 10), cv::FILLED);
    }
  return image;
}

cv::Rect draw_pedestrian(cv::Mat& image, cv::Point corner, int h, cv::Scalar shirt,
                         cv::Scalar trousers) {
  const int w = h / 3;
  cv::rectangle(image, cv::Rect(corner.x, corner.y, w, h / 2), shirt, cv::FILLED);
  cv::rectangle(image, cv::Rect(corner.x, corner.y + h / 2, w, h - h / 2), trousers, cv::FILLED);
  return {corner.x, corner.y, w, h};
}

// A synthetic sequence: the target walks right at 2 px per frame; a green pedestrian walks
// left past it in front (covering part of it), then a wide grey pillar hides it entirely.
//
//   frames 0-29    clear
//   frames 30-49   partial: the green pedestrian covers about half the target's width
//   frames 60-69   full: behind the pillar
//   frames 70-99   clear again
//
// While partly covered the target is held when the box lies on it (at least 80 % of the box
// inside its true box): the kernel sizes follow its last box and the one chosen is the box the
// acceptance test likes best, which is then its visible part, not the whole body.
TEST(tracker, holds_through_partial_occlusion_and_regains_after_full) {
  const cv::Scalar red(30, 30, 200), blue(140, 60, 20), green(40, 170, 40), pink(180, 80, 230);
  const cv::Mat floor = background(3);
  auto frame_at = [&](int k, cv::Rect& truth, bool& hidden) {
    cv::Mat frame = floor.clone();
    truth = draw_pedestrian(frame, {20 + 2 * k, 60}, 90, red, blue);
    hidden = false;
    if (k >= 30 && k < 50) {
      draw_pedestrian(frame, {truth.x + truth.width / 2, 70}, 90, green, pink);
    }
    if (k >= 60 && k < 70) {
      cv::rectangle(frame, cv::Rect(truth.x - 15, 0, truth.width + 30, 240),
                    cv::Scalar(128, 128, 128), cv::FILLED);
      hidden = true;
    }
    return frame;
  };
  cv::Rect truth;
  bool hidden = false;
  auto first = frame_at(0, truth, hidden);
  tracker t(color_histogram::of_region(first, truth));
  t.start(truth);
  int held = 0, lost_while_hidden = 0, regained = 0;
  for (int k = 1; k < 100; ++k) {
    auto frame = frame_at(k, truth, hidden);
    auto seen = t.update(frame);
    const bool on_target = seen.found && (seen.box & truth).area() >= 0.8 * seen.box.area();
    if (k >= 30 && k < 50) held += on_target ? 1 : 0;
    if (hidden) lost_while_hidden += seen.found ? 0 : 1;
    if (k >= 75) regained += seen.found && overlap(seen.box, truth) > 0.5 ? 1 : 0;
    if (k < 30) {
      EXPECT_TRUE(seen.found && overlap(seen.box, truth) > 0.5) << "frame " << k;
    }
  }
  EXPECT_EQ(held, 20);               // every partially occluded frame
  EXPECT_EQ(lost_while_hidden, 10);  // lost track reported behind the pillar
  EXPECT_EQ(regained, 25);           // and regained after it
}

// sensing.identity: ground_truth hands the tracker a check that stands for a perfect identity
// test: she leaves the frame while a twin stays in it. The paper's tracker takes the twin; with
// the check the track is lost, and found again when she comes back.
TEST(tracker, a_find_the_check_refuses_is_no_find) {
  const cv::Scalar red(30, 30, 200), blue(140, 60, 20);
  const cv::Mat floor = background(7);
  cv::Mat both = floor.clone();
  const auto her = draw_pedestrian(both, {60, 60}, 90, red, blue);
  const auto twin = draw_pedestrian(both, {220, 70}, 90, red, blue);
  cv::Mat twin_only = floor.clone();
  draw_pedestrian(twin_only, twin.tl(), 90, red, blue);
  const auto signature = color_histogram::of_region(both, her).normalized();
  const tracker::find_check on_her = [&](const cv::Rect& box) {
    return (box & her).area() > box.area() / 2;
  };

  tracker paper(signature);
  paper.start(her);
  ASSERT_TRUE(paper.update(both).found);
  const auto taken = paper.update(twin_only);
  ASSERT_TRUE(taken.found) << "without the check, the twin is taken for her";
  EXPECT_GT((taken.box & twin).area(), taken.box.area() / 2);

  tracker checked(signature);
  checked.start(her);
  ASSERT_TRUE(checked.update(both, on_her).found);
  for (int frame = 0; frame < 3; ++frame) {
    EXPECT_FALSE(checked.update(twin_only, on_her).found) << "frame " << frame;
    EXPECT_TRUE(checked.lost());
  }
  const auto back = checked.update(both, on_her);
  ASSERT_TRUE(back.found) << "she is found again where she is";
  EXPECT_GT((back.box & her).area(), back.box.area() / 2);
}

ptz_limits ptz_head() {
  ptz_limits limits;
  limits.pan = {-90.0, 90.0};
  limits.tilt = {-60.0, 0.0};
  limits.field_of_view = {10.0, 60.0};
  return limits;
}

// track_rho: a live track is kept on a box in its window that scores above track_rho, while a
// find anywhere else must still score above rho. Her top has turned green in the frame looked
// at (a shadow, another camera's colours), so she matches her red-and-blue signature by about
// half.
TEST(tracker, a_live_track_is_kept_above_track_rho_a_new_find_needs_rho) {
  const cv::Scalar red(30, 30, 200), blue(140, 60, 20), green(40, 170, 40);
  const cv::Mat floor = background(5);
  cv::Mat first = floor.clone();
  const auto her = draw_pedestrian(first, {100, 60}, 90, red, blue);
  const auto signature = color_histogram::of_region(first, her).normalized();
  cv::Mat changed = floor.clone();
  draw_pedestrian(changed, {100, 60}, 90, green, blue);

  tracker_settings one_threshold;
  one_threshold.rho = 0.6;
  tracker paper(signature, one_threshold);
  paper.start(her);
  EXPECT_FALSE(paper.update(changed).found) << "half her colours are below rho";

  auto hysteresis = one_threshold;
  hysteresis.track_rho = 0.35;
  tracker kept(signature, hysteresis);
  kept.start(her);
  for (int frame = 0; frame < 5; ++frame) {
    const auto seen = kept.update(changed);
    ASSERT_TRUE(seen.found) << "frame " << frame;
    EXPECT_TRUE(her.contains((seen.box.tl() + seen.box.br()) / 2)) << "on her, frame " << frame;
    EXPECT_GT((seen.box & her).area(), seen.box.area() / 2) << "frame " << frame;
    EXPECT_LT(seen.score, 0.6);
  }
  EXPECT_FALSE(tracker(signature, hysteresis).update(changed).found)
      << "a whole-frame find, no track yet: rho applies";
}

TEST(tracking_fsm, wait_widens_the_zoom_then_search_sweeps_then_fails) {
  config::controller_settings controller;  // Table 2: wait 2 min, search 5 min
  tracking_fsm fsm(ptz_head(), controller);
  const frame_size frame{320, 240};
  const config::seconds dt{1.0 / 15.0};
  ptz_state pose{0.0, -20.0, 20.0};
  track_observation seen{true, cv::Rect(150, 80, 20, 60), 0.9};
  auto command = fsm.step(seen, pose, frame, dt);
  EXPECT_EQ(command.state, tracking_state::track);
  pose = command.pose;

  track_observation lost{false, seen.box, 0.0};
  command = fsm.step(lost, pose, frame, dt);
  EXPECT_EQ(command.state, tracking_state::wait);
  double fov = pose.field_of_view_deg;
  for (int k = 0; k < 15 * 10; ++k) {  // 10 s of Wait: the zoom widens, pan and tilt hold
    command = fsm.step(lost, pose, frame, dt);
    EXPECT_EQ(command.state, tracking_state::wait);
    EXPECT_GE(command.pose.field_of_view_deg, pose.field_of_view_deg);
    EXPECT_EQ(command.pose.pan_deg, pose.pan_deg);
    pose = command.pose;
  }
  EXPECT_NEAR(pose.field_of_view_deg - fov, 2.0 * 10.0, 0.5);  // 2 deg/s, gradually

  // Reacquired in Wait: back to Track.
  EXPECT_EQ(fsm.step(seen, pose, frame, dt).state, tracking_state::track);
  fsm.step(lost, pose, frame, dt);
  // Wait times out after 2 min into Search, which sweeps pan at the widest FOV.
  int frames = 0;
  while (fsm.step(lost, pose, frame, dt).state == tracking_state::wait) ++frames;
  EXPECT_NEAR(frames * dt.count(), 120.0, 0.2);
  EXPECT_EQ(fsm.state(), tracking_state::search);
  double min_pan = 0.0, max_pan = 0.0;
  for (int k = 0; k < 15 * 30; ++k) {
    command = fsm.step(lost, pose, frame, dt);
    pose = command.pose;
    min_pan = std::min(min_pan, pose.pan_deg);
    max_pan = std::max(max_pan, pose.pan_deg);
  }
  EXPECT_EQ(pose.field_of_view_deg, 60.0);
  EXPECT_EQ(max_pan, 90.0);  // swept to both limits
  EXPECT_EQ(min_pan, -90.0);
  // Search times out after 5 min: the task failed.
  for (int k = 0; k < 15 * 300 && fsm.state() == tracking_state::search; ++k)
    pose = fsm.step(lost, pose, frame, dt).pose;
  EXPECT_EQ(fsm.state(), tracking_state::failed);
  fsm.reset();
  EXPECT_EQ(fsm.state(), tracking_state::track);
}

TEST(tracking_fsm, track_fixates_on_the_box) {
  tracking_fsm fsm(ptz_head(), config::controller_settings{});
  ptz_state pose{0.0, -20.0, 30.0};
  // Target right of and above the centre: pan right (negative), tilt up.
  auto command = fsm.step({true, cv::Rect(250, 20, 20, 60), 0.9}, pose, {320, 240},
                          config::seconds{1.0 / 15.0});
  EXPECT_LT(command.pose.pan_deg, 0.0);
  EXPECT_GT(command.pose.tilt_deg, -20.0);
}

TEST(tracking_fsm, a_static_camera_holds_its_pose_in_every_state) {
  config::controller_settings controller;
  controller.wait_timeout = config::seconds{1.0};
  controller.search_timeout = config::seconds{20.0};
  tracking_fsm fsm(ptz_limits::from(test_support::static_camera()), controller);
  const ptz_state fixed{30.0, -25.0, 40.0};
  const config::seconds dt{1.0 / 15.0};
  EXPECT_EQ(fsm.step({true, cv::Rect(300, 10, 4, 12), 0.9}, fixed, {320, 240}, dt).pose, fixed);
  track_observation lost{false, cv::Rect(300, 10, 4, 12), 0.0};
  bool searched = false;
  for (int k = 0; k < 15 * 30 && fsm.state() != tracking_state::failed; ++k) {
    const auto command = fsm.step(lost, fixed, {320, 240}, dt);
    searched = searched || command.state == tracking_state::search;
    EXPECT_EQ(command.pose, fixed) << "frame " << k;
  }
  EXPECT_TRUE(searched);
  EXPECT_EQ(fsm.state(), tracking_state::failed);
}

TEST(tracking_fsm, search_turns_all_the_way_round_when_pan_wraps) {
  ptz_limits limits;  // pan [-180, 180]: no limit to sweep to
  config::controller_settings controller;
  controller.wait_timeout = config::seconds{1.0};
  tracking_fsm fsm(limits, controller);
  const config::seconds dt{1.0 / 15.0};
  ptz_state pose{0.0, -20.0, 45.0};
  track_observation lost{false, cv::Rect(150, 80, 20, 60), 0.0};
  fsm.step({true, lost.box, 0.9}, pose, {320, 240}, dt);
  while (fsm.step(lost, pose, {320, 240}, dt).state != tracking_state::search) {
  }
  // 60 deg/s: a turn takes 6 s. Over 20 s the sweep turns, steps a row, turns back.
  double turned = 0.0, most_turned = 0.0;
  bool came_back = false;
  std::vector<double> tilts{pose.tilt_deg};
  for (int k = 0; k < 15 * 20; ++k) {
    const auto next = fsm.step(lost, pose, {320, 240}, dt).pose;
    turned += std::remainder(next.pan_deg - pose.pan_deg, 360.0);
    most_turned = std::max(most_turned, turned);
    came_back = came_back || (most_turned >= 360.0 && std::abs(turned) < 10.0);
    if (next.tilt_deg != tilts.back()) tilts.push_back(next.tilt_deg);
    EXPECT_GT(next.pan_deg, -180.0);
    EXPECT_LE(next.pan_deg, 180.0);
    pose = next;
  }
  EXPECT_GE(most_turned, 360.0);  // one way all the way round
  EXPECT_TRUE(came_back);         // then back
  EXPECT_GE(tilts.size(), 2u);    // on another row
  EXPECT_EQ(pose.field_of_view_deg, 90.0);
}

}  // namespace
}  // namespace argus::vision
