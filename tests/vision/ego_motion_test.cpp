#include "vision/ego_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "opencv2/imgproc.hpp"
#include "vision/fixate_zoom.hpp"
#include "vision/tracker.hpp"

namespace argus::vision {
namespace {

constexpr double deg = std::numbers::pi / 180.0;
const frame_size frame{320, 240};

cv::Point2d centre_of(const cv::Rect2d& box) {
  return {box.x + box.width / 2.0, box.y + box.height / 2.0};
}

TEST(ego_motion, a_pan_moves_the_image_centre_by_the_focal_length_times_the_tangent) {
  const ptz_state from{30.0, 0.0, 40.0}, to{25.0, 0.0, 40.0};
  const cv::Rect2d box(150.0, 100.0, 20.0, 40.0);  // centred on the image
  const auto moved = reproject_box(box, from, to, frame);
  ASSERT_TRUE(moved);
  // Panning 5 degrees to the right-hand (negative) side brings what was ahead to the left.
  const double f = focal_length_px(40.0, 320);
  EXPECT_NEAR(centre_of(*moved).x, 160.0 - f * std::tan(5.0 * deg), 1e-6);
  EXPECT_NEAR(centre_of(*moved).y, 120.0, 1e-6);
  EXPECT_NEAR(moved->width, 20.0, 1e-9);
}

TEST(ego_motion, zooming_in_scales_the_box_about_the_image_centre) {
  const ptz_state from{0.0, -10.0, 40.0}, to{0.0, -10.0, 20.0};
  const cv::Rect2d box(200.0, 140.0, 10.0, 30.0);
  const auto moved = reproject_box(box, from, to, frame);
  ASSERT_TRUE(moved);
  const double k = focal_length_px(20.0, 320) / focal_length_px(40.0, 320);
  EXPECT_NEAR(moved->height, 30.0 * k, 1e-9);
  EXPECT_NEAR(centre_of(*moved).x - 160.0, (205.0 - 160.0) * k, 1e-6);
  EXPECT_NEAR(centre_of(*moved).y - 120.0, (155.0 - 120.0) * k, 1e-6);
}

TEST(ego_motion, the_pose_that_centres_a_box_shows_it_at_the_centre) {
  const ptz_state from{-140.0, -12.0, 50.0};
  const cv::Rect2d box(12.0, 70.0, 9.0, 25.0);  // at the left edge, as a new target often is
  const auto goal = centring_pose(from, box, frame, 0.5);
  const auto moved = reproject_box(box, from, goal, frame);
  ASSERT_TRUE(moved);
  EXPECT_NEAR(centre_of(*moved).x, 160.0, 1e-6);
  EXPECT_NEAR(centre_of(*moved).y, 120.0, 1e-6);
  EXPECT_NEAR(moved->height, 120.0, 0.5);  // half the frame, as centring_pose was asked
  // And back again.
  const auto back = reproject_box(*moved, goal, from, frame);
  ASSERT_TRUE(back);
  EXPECT_NEAR(back->x, box.x, 1e-6);
  EXPECT_NEAR(back->y, box.y, 1e-6);
  EXPECT_NEAR(back->height, box.height, 1e-6);
}

TEST(ego_motion, a_ray_behind_the_camera_has_no_box) {
  EXPECT_FALSE(
      reproject_box({150.0, 100.0, 20.0, 40.0}, {0.0, 0.0, 40.0}, {180.0, 0.0, 40.0}, frame));
}

// A red-and-blue figure on a grey floor, a look-alike elsewhere: the camera fixates so fast
// that the figure moves 90 px in the image between two frames, beyond the search window
// around its last box (one box size on every side). With the camera's motion followed, the
// tracker finds it in that window where it now is; without, the window holds only floor (the
// tracker may then search the whole frame, where the look-alike is as likely).
TEST(ego_motion, a_tracker_that_follows_its_camera_keeps_a_target_the_pan_moved) {
  const cv::Scalar grey(120, 120, 120), red(30, 30, 200), blue(140, 60, 20);
  auto scene = [&](double pan_deg) {
    // The figure stands at pan 0 (a ray along the camera's pan-0 axis), the look-alike 25
    // degrees to its right; both at tilt 0, 24 x 72 px at this field of view.
    cv::Mat image(240, 320, CV_8UC3, grey);
    const double f = focal_length_px(40.0, 320);
    for (double at : {0.0, -25.0}) {
      const int x = static_cast<int>(std::lround(160.0 - f * std::tan((at - pan_deg) * deg)));
      cv::rectangle(image, cv::Rect(x - 12, 84, 24, 36), red, cv::FILLED);
      cv::rectangle(image, cv::Rect(x - 12, 120, 24, 36), blue, cv::FILLED);
    }
    return image;
  };
  const ptz_state before{-12.0, 0.0, 40.0}, after{-2.0, 0.0, 40.0};
  const double f = focal_length_px(40.0, 320);
  const int x0 = static_cast<int>(std::lround(160.0 - f * std::tan(12.0 * deg)));
  const int x1 = static_cast<int>(std::lround(160.0 - f * std::tan(2.0 * deg)));
  ASSERT_GT(std::abs(x1 - x0), 3 * 24);  // beyond the window
  const cv::Rect start(x0 - 12, 84, 24, 72);
  const auto first = scene(before.pan_deg);
  const auto target = color_histogram::of_region(first, start).normalized();
  for (const bool follow : {true, false}) {
    tracker_settings settings;
    settings.ego_motion = follow;
    settings.search_whole_frame = false;
    tracker t(target, settings);
    t.start(start);
    if (follow) t.follow_camera(before, after, frame);
    const auto seen = t.update(scene(after.pan_deg));
    if (follow) {
      ASSERT_TRUE(seen.found);
      EXPECT_NEAR(seen.box.x + seen.box.width / 2.0, x1, 4.0);
      EXPECT_NEAR(seen.box.height, 72.0, 12.0);
    } else {
      EXPECT_FALSE(seen.found) << "the window around the last box held only floor";
    }
  }
}

// The camera zooms in on a small figure at the image centre, from a 60 to a 30 degree field of
// view: she grows from 13 to 28 px tall, about 2.5 % a frame, and the tracker's box must grow
// with her. Its sizes are 6 px apart in height; a box carried by the zoom but then snapped to
// the size found, every frame, loses each frame's growth to that rounding and falls behind
// her (19 px at the end, against her 28; in two_tasks.yaml's first seconds 13 px against her
// 19-37, until a miss).
TEST(ego_motion, a_tracker_zooming_in_on_a_small_figure_grows_its_box_with_her) {
  const cv::Scalar grey(120, 120, 120), red(30, 30, 200), blue(140, 60, 20);
  auto figure = [](double height) {
    const int h = static_cast<int>(std::lround(height));
    const int w = std::max(1, static_cast<int>(std::lround(height / 3.0)));
    return cv::Rect(160 - w / 2, 120 - h / 2, w, h);
  };
  auto scene = [&](const cv::Rect& her) {
    cv::Mat image(240, 320, CV_8UC3, grey);
    cv::rectangle(image, cv::Rect(her.x, her.y, her.width, her.height / 2), red, cv::FILLED);
    cv::rectangle(image,
                  cv::Rect(her.x, her.y + her.height / 2, her.width, her.height - her.height / 2),
                  blue, cv::FILLED);
    return image;
  };
  ptz_state pose{0.0, 0.0, 60.0};
  const double first_height = 13.0;
  const cv::Rect start = figure(first_height);
  tracker_settings settings;
  settings.ego_motion = true;
  settings.search_whole_frame = false;
  tracker t(color_histogram::of_region(scene(start), start).normalized(), settings);
  t.start(start);
  cv::Rect her = start;
  track_observation seen;
  for (int k = 0; k < 30; ++k) {
    ptz_state next = pose;
    next.field_of_view_deg -= 1.0;
    t.follow_camera(pose, next, frame);
    pose = next;
    her = figure(first_height * focal_length_px(pose.field_of_view_deg, 320) /
                 focal_length_px(60.0, 320));
    seen = t.update(scene(her));
    ASSERT_TRUE(seen.found) << "frame " << k;
  }
  ASSERT_GE(her.height, 27);
  // Within one of the localiser's sizes of hers.
  EXPECT_NEAR(seen.box.height, her.height, 6.0);
}

}  // namespace
}  // namespace argus::vision
