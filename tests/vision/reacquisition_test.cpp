// How a tracker takes a target up again from the whole frame: the paper's takes the first region
// above rho, whoever it shows; with reacquire_margin it wants a margin over the best look-alike,
// and with local_search_frames it looks where she was lost before it looks everywhere.

#include <gtest/gtest.h>

#include "opencv2/imgproc.hpp"
#include "vision/tracker.hpp"

namespace argus::vision {
namespace {

const cv::Scalar grey(120, 120, 120), red(30, 30, 200), blue(140, 60, 20);

// A red-over-blue figure 60 px tall with its box's left edge at `x`.
cv::Rect draw_figure(cv::Mat& image, int x) {
  cv::rectangle(image, cv::Rect(x, 80, 20, 30), red, cv::FILLED);
  cv::rectangle(image, cv::Rect(x, 110, 20, 30), blue, cv::FILLED);
  return {x, 80, 20, 60};
}

int centre_x(const cv::Rect& box) {
  return box.x + box.width / 2;
}

TEST(reacquisition, a_margin_over_the_best_look_alike_refuses_a_tie) {
  cv::Mat alone(240, 320, CV_8UC3, grey);
  const auto her = draw_figure(alone, 60);
  const auto signature = color_histogram::of_region(alone, her).normalized();
  cv::Mat twins = alone.clone();
  draw_figure(twins, 240);
  tracker_settings paper;
  EXPECT_TRUE(tracker(signature, paper).update(twins).found) << "the paper's takes either";
  tracker_settings margin;
  margin.reacquire_margin = 0.05;
  EXPECT_FALSE(tracker(signature, margin).update(twins).found) << "two alike: neither is her";
  const auto seen = tracker(signature, margin).update(alone);
  ASSERT_TRUE(seen.found) << "alone she is taken";
  EXPECT_NEAR(centre_x(seen.box), centre_x(her), 3);
}

// She walks behind something for a frame (not drawn) while a look-alike stands across the
// frame, then reappears 2 px on:
//
//   frame 0: [her]          [twin]     frame 1:        [twin]     frame 2:  [her]    [twin]
TEST(reacquisition, a_local_search_waits_for_her_where_she_was_lost) {
  cv::Mat first(240, 320, CV_8UC3, grey);
  const auto start = draw_figure(first, 60);
  draw_figure(first, 240);
  const auto signature = color_histogram::of_region(first, start).normalized();
  cv::Mat hidden(240, 320, CV_8UC3, grey);
  draw_figure(hidden, 240);
  cv::Mat back = hidden.clone();
  const auto her = draw_figure(back, 62);
  {
    tracker t(signature, tracker_settings{});
    t.start(start);
    const auto seen = t.update(hidden);
    ASSERT_TRUE(seen.found) << "the paper's tracker takes the look-alike";
    EXPECT_NEAR(centre_x(seen.box), 250, 3);
  }
  tracker_settings local;
  local.local_search_frames = 10;
  tracker t(signature, local);
  t.start(start);
  EXPECT_FALSE(t.update(hidden).found);
  const auto seen = t.update(back);
  ASSERT_TRUE(seen.found);
  EXPECT_NEAR(centre_x(seen.box), centre_x(her), 3);
}

}  // namespace
}  // namespace argus::vision
