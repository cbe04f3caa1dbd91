// The signature in halves (signature_halves, tracker_settings::halves_rho): a red shirt over
// blue trousers and a blue shirt over red trousers have one histogram, which the paper's tracker
// cannot tell apart; their halves differ, and a tracker testing them takes only her.

#include "vision/signature_halves.hpp"

#include <gtest/gtest.h>

#include "opencv2/imgproc.hpp"
#include "vision/tracker.hpp"

namespace argus::vision {
namespace {

const cv::Scalar wall(120, 120, 120), blue(140, 60, 20), red(30, 30, 200), skin(120, 160, 210);

// A figure 60 px tall at column x: an 8 px head, then as much `shirt` as `trousers`.
cv::Rect draw_figure(cv::Mat& image, int x, const cv::Scalar& shirt, const cv::Scalar& trousers) {
  cv::rectangle(image, cv::Rect(x, 80, 20, 8), skin, cv::FILLED);
  cv::rectangle(image, cv::Rect(x, 88, 20, 26), shirt, cv::FILLED);
  cv::rectangle(image, cv::Rect(x, 114, 20, 26), trousers, cv::FILLED);
  return {x, 80, 20, 60};
}

signature_halves halves_at(const cv::Mat& bgr, const cv::Rect& box) {
  const histogram_bins bins;
  return halves_in(bin_index_image(bgr, bins), box, bins);
}

TEST(signature_halves, the_upper_half_starts_below_the_head_and_the_halves_meet) {
  const auto halves = halves_of({10, 80, 20, 64});
  EXPECT_EQ(halves.upper, cv::Rect(10, 88, 20, 24));
  EXPECT_EQ(halves.lower, cv::Rect(10, 112, 20, 32));
  const auto tiny = halves_of({0, 0, 3, 2});
  EXPECT_EQ(tiny.upper.height, 1);
  EXPECT_EQ(tiny.lower.height, 1);
  EXPECT_TRUE(halves_of({}).upper.empty());
}

TEST(signature_halves, halves_are_compared_in_hue_and_coarser_saturation_without_brightness) {
  const histogram_bins fine;
  EXPECT_EQ(halves_comparison_bins(fine), (histogram_bins{8, 4, 1}));
  color_histogram h(fine);
  // Hue bin 5, saturation bin 3, value bins 0 and 3: one coarse bin, (5, 1, 0).
  h.counts()[(5 * 8 + 3) * 4 + 0] = 2.0f;
  h.counts()[(5 * 8 + 3) * 4 + 3] = 1.0f;
  h.counts()[(7 * 8 + 7) * 4 + 2] = 4.0f;
  const auto merged = merged_into(h, halves_comparison_bins(fine));
  EXPECT_EQ(merged.total(), 7.0);
  EXPECT_EQ(merged[5 * 4 + 1], 3.0f);
  EXPECT_EQ(merged[7 * 4 + 3], 4.0f);
}

TEST(signature_halves, swapped_clothes_match_in_one_histogram_but_not_in_halves) {
  cv::Mat image(240, 320, CV_8UC3, wall);
  const auto her = draw_figure(image, 60, red, blue);
  const auto him = draw_figure(image, 200, blue, red);
  const histogram_bins bins;
  const auto indices = bin_index_image(image, bins);
  EXPECT_GT(
      normalized_intersection(color_histogram::of_bin_indices(indices, her, bins).normalized(),
                              color_histogram::of_bin_indices(indices, him, bins).normalized()),
      0.95);
  EXPECT_GT(halves_match(halves_at(image, her), halves_at(image, her)), 0.99);
  EXPECT_LT(halves_match(halves_at(image, her), halves_at(image, him)), 0.3);
  EXPECT_EQ(halves_match(halves_at(image, her), halves_at(image, {400, 0, 20, 60})), 0.0)
      << "a box outside the image has empty halves";
}

TEST(signature_halves, a_tracker_testing_halves_refuses_him_and_takes_her) {
  cv::Mat with_both(240, 320, CV_8UC3, wall);
  const auto her = draw_figure(with_both, 220, red, blue);
  const auto signature = color_histogram::of_region(with_both, her).normalized();
  const auto halves = halves_at(with_both, her);
  cv::Mat only_him(240, 320, CV_8UC3, wall);
  draw_figure(only_him, 60, blue, red);
  draw_figure(with_both, 60, blue, red);

  EXPECT_TRUE(tracker(signature).update(only_him).found)
      << "the paper's tracker takes him for her: one histogram";
  tracker_settings in_halves;
  in_halves.halves_rho = 0.5;
  EXPECT_FALSE(tracker(signature, in_halves, halves).update(only_him).found);
  EXPECT_TRUE(tracker(signature, in_halves).update(only_him).found)
      << "without her halves there is nothing to test";
  const auto seen = tracker(signature, in_halves, halves).update(with_both);
  ASSERT_TRUE(seen.found);
  EXPECT_GT((seen.box & her).area(), her.area() / 2);
}

}  // namespace
}  // namespace argus::vision
