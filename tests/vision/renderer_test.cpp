// Runs on whatever EGL device the machine has: Mesa llvmpipe through the surfaceless platform
// on a CPU-only machine (CI), the NVIDIA driver on a GPU machine.

#include "vision/renderer.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/support/walking_crowd.hpp"
#include "vision/imaging_model.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::vision {
namespace {

// Intensity-weighted centroid of the pixels brighter than `threshold` (in the first channel
// the marker lights: all of them for white).
std::optional<Eigen::Vector2d> bright_centroid(const cv::Mat& bgr, int threshold = 128) {
  cv::Mat gray;
  cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  cv::Mat mask = gray > threshold;
  const cv::Moments m = cv::moments(mask, true);
  if (m.m00 == 0.0) return std::nullopt;
  return Eigen::Vector2d{m.m10 / m.m00, m.m01 / m.m00};
}

TEST(renderer, reports_its_device) {
  renderer r(nullptr);
  EXPECT_FALSE(r.device().empty());
  std::cout << "rendering with: " << r.device() << '\n';
}

TEST(renderer, marker_renders_where_the_camera_model_projects_it) {
  renderer r(nullptr);
  struct pose_case {
    Eigen::Vector3d camera;
    ptz_state pose;
    Eigen::Vector3d point;
  };
  const pose_case cases[] = {
      {{0.0, 0.0, 8.0}, {0.0, -20.0, 60.0}, {20.0, 3.0, 1.0}},
      {{50.0, 50.0, 6.0}, {-130.0, -35.0, 40.0}, {42.0, 40.0, 0.5}},
      {{10.0, 80.0, 4.0}, {75.0, 5.0, 20.0}, {13.0, 100.0, 6.5}},
      {{5.0, 5.0, 10.0}, {30.0, -60.0, 90.0}, {6.0, 12.0, 0.0}},
  };
  for (const auto& c : cases) {
    for (auto [w, h] : {std::pair{640, 480}, std::pair{320, 240}}) {
      camera_view view{{c.camera}, c.pose, w, h};
      const auto expected = view.project(c.point);
      ASSERT_TRUE(expected);
      ASSERT_GT(expected->x(), 10.0);
      ASSERT_LT(expected->x(), w - 10.0);
      ASSERT_GT(expected->y(), 10.0);
      ASSERT_LT(expected->y(), h - 10.0);
      // Size the marker to about 6 px whatever the distance.
      const double distance = (c.point - c.camera).norm();
      const marker m{c.point, 6.0 * distance / view.focal_px()};
      const cv::Mat image = r.render_markers(view, std::span{&m, 1});
      ASSERT_EQ(image.type(), CV_8UC3);
      ASSERT_EQ(image.cols, w);
      ASSERT_EQ(image.rows, h);
      const auto seen = bright_centroid(image);
      ASSERT_TRUE(seen) << "marker not visible";
      EXPECT_LT((*seen - *expected).norm(), 1.0)
          << "pose pan " << c.pose.pan_deg << " tilt " << c.pose.tilt_deg << " fov "
          << c.pose.field_of_view_deg << " at " << w << "x" << h << ": expected "
          << expected->transpose() << ", seen " << seen->transpose();
    }
  }
}

TEST(renderer, marker_colour_comes_out_in_bgr_order) {
  renderer r(nullptr);
  camera_view view{{{0.0, 0.0, 2.0}}, {0.0, 0.0, 30.0}, 64, 48};
  const marker m{{10.0, 0.0, 2.0}, 2.0, {250, 10, 20}};  // red
  const cv::Mat image = r.render_markers(view, std::span{&m, 1});
  const cv::Vec3b centre = image.at<cv::Vec3b>(24, 32);
  EXPECT_EQ(centre, cv::Vec3b(20, 10, 250));
  EXPECT_EQ(image.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
}

// One walking pedestrian crossing the view left to right.
world::pedestrian_state walker(double x) {
  world::pedestrian_state p;
  p.id = 3;
  p.position = {x, 6.0};
  p.velocity = {1.4, 0.0};
  p.placed_heading_rad = 0.0;
  p.look.shirt = {200, 30, 30};
  p.look.trousers = {30, 30, 120};
  p.look.skin = {220, 180, 150};
  p.look.hair = {40, 30, 20};
  return p;
}

// Sum of |row 2k - row 2k+1| over the frame: how "combed" it looks.
double combing(const cv::Mat& f) {
  double sum = 0.0;
  for (int y = 0; y + 1 < f.rows; y += 2) sum += cv::norm(f.row(y), f.row(y + 1), cv::NORM_L1);
  return sum;
}

TEST(renderer, interlaced_frames_of_a_moving_figure_differ_between_even_and_odd_rows) {
  renderer r(nullptr);
  camera_view view{{{0.0, 0.0, 1.5}}, {90.0, -5.0, 40.0}, 320, 240};
  // The second field is rendered half a frame (1/30 s) later, the walker 1.4 m/s further.
  // A fast-moving figure (as in Fig. 6) shows it clearly: use 4 m/s.
  auto first = walker(-1.0);
  auto second = walker(-1.0 + 4.0 / 30.0);
  const cv::Mat f1 = r.render(view, std::span{&first, 1}, 0.0);
  const cv::Mat f2 = r.render(view, std::span{&second, 1}, 1.0 / 30.0);
  const cv::Mat woven = weave_fields(f1, f2);
  EXPECT_GT(cv::norm(f1, f2, cv::NORM_L1), 0.0);
  EXPECT_GT(combing(woven), 1.5 * std::max(combing(f1), combing(f2)));
}

TEST(renderer, penn_station_frame_shows_shirt_colours_where_the_camera_model_puts_them) {
  const auto& scene = ::argus::test_support::walking_crowd();
  const auto& frame = *scene.frame;
  renderer r(scene.station);
  // Camera 2 of scenarios/penn_station.yaml: north wall of the waiting room, looking south.
  camera_view view{{{103.0, 87.0, 8.0}}, {-90.0, -20.0, 60.0}, 640, 480};
  const cv::Mat image = r.render(view, frame, frame.time().count());
  cv::imwrite("renderer_test_penn_station.png", image);  // for a human to look at
  int checked = 0;
  int matched = 0;
  for (const auto& p : frame.pedestrians()) {
    if (p.doing == world::activity::sitting) continue;
    const double distance =
        (Eigen::Vector3d{p.position.x(), p.position.y(), 1.2} - view.placement.position_m).norm();
    if (distance > 30.0) continue;
    // Middle of the torso: 0.47 h (hips) + 0.33 h / 2.
    const auto px = view.project({p.position.x(), p.position.y(), 0.63 * p.look.height_m});
    if (!px || px->x() < 3 || px->y() < 3 || px->x() > 636 || px->y() > 476) continue;
    ++checked;
    // Lambert lighting scales the colour: look for k * shirt within 3 px.
    const Eigen::Vector3d shirt{p.look.shirt.b / 1.0, p.look.shirt.g / 1.0, p.look.shirt.r / 1.0};
    bool found = false;
    for (int dy = -3; dy <= 3 && !found; ++dy) {
      for (int dx = -3; dx <= 3 && !found; ++dx) {
        const auto c =
            image.at<cv::Vec3b>(static_cast<int>(px->y()) + dy, static_cast<int>(px->x()) + dx);
        const Eigen::Vector3d v{c[0] / 1.0, c[1] / 1.0, c[2] / 1.0};
        const double k = v.dot(shirt) / std::max(1.0, shirt.squaredNorm());
        found = k > 0.3 && k < 1.3 && (v - k * shirt).norm() < 12.0;
      }
    }
    if (found) ++matched;
  }
  ASSERT_GE(checked, 5) << "too few pedestrians near camera 2 to test";
  // Some may be hidden behind others or a bench.
  EXPECT_GE(matched, checked * 8 / 10) << matched << " of " << checked;
}

// The fraction of pixels that differ in any channel, and the mean absolute difference per
// channel, between two frames of the same size.
std::pair<double, double> difference(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  cv::Mat any;
  cv::transform(diff, any, cv::Matx13f(1.0f, 1.0f, 1.0f));
  const double differing = cv::countNonZero(any) / static_cast<double>(a.total());
  const cv::Scalar mean = cv::mean(diff);
  return {differing, (mean[0] + mean[1] + mean[2]) / 3.0};
}

// What renderer::render_interlaced promises: the rows of two full renders woven together, up
// to rounding at the edges of shapes, in the station with a crowd walking (the gait moves
// between the fields), for an even and an odd number of rows.
TEST(renderer, interlaced_frame_in_one_pass_is_two_full_renders_woven) {
  const auto& scene = ::argus::test_support::walking_crowd();
  const auto& frame = *scene.frame;
  renderer r(scene.station);
  const double t = frame.time().count();
  for (const int rows : {240, 241}) {
    // Camera 2 of scenarios/penn_station.yaml, and camera 7 (the arcade), zoomed in.
    for (const auto& view : {camera_view{{{103.0, 87.0, 8.0}}, {-90.0, -20.0, 60.0}, 320, rows},
                             camera_view{{{197.0, 62.0, 5.0}}, {-165.0, -15.0, 20.0}, 320, rows}}) {
      const cv::Mat one_pass = r.render_interlaced(view, frame, t, t + 1.0 / 30.0);
      const cv::Mat woven =
          weave_fields(r.render(view, frame, t), r.render(view, frame, t + 1.0 / 30.0));
      ASSERT_EQ(one_pass.size(), woven.size());
      const auto [differing, mean_abs] = difference(one_pass, woven);
      std::cout << rows << " rows, pan " << view.pose.pan_deg << ": " << 100.0 * differing
                << " % of pixels differ, by " << mean_abs << " grey levels on average\n";
      // Measured: at most 0.11 % of pixels, 0.11 grey levels (llvmpipe, 2026-12-05).
      EXPECT_LT(differing, 0.005);
      EXPECT_LT(mean_abs, 0.25);
      // Not a copy of one field: the odd rows are the second field's.
      EXPECT_GT(cv::norm(one_pass, r.render(view, frame, t), cv::NORM_L1), 0.0);
    }
  }
}

TEST(renderer, interlaced_frame_of_a_moving_figure_in_one_pass_is_combed_as_the_woven_one) {
  renderer r(nullptr);
  camera_view view{{{0.0, 0.0, 1.5}}, {90.0, -5.0, 40.0}, 320, 240};
  auto first = walker(-1.0);
  auto second = walker(-1.0 + 4.0 / 30.0);
  const cv::Mat one_pass =
      r.render_interlaced(view, std::span{&first, 1}, 0.0, std::span{&second, 1}, 1.0 / 30.0);
  const cv::Mat woven = weave_fields(r.render(view, std::span{&first, 1}, 0.0),
                                     r.render(view, std::span{&second, 1}, 1.0 / 30.0));
  EXPECT_NEAR(combing(one_pass), combing(woven), 0.05 * combing(woven));
  EXPECT_LT(difference(one_pass, woven).first, 0.01);
}

}  // namespace
}  // namespace argus::vision
