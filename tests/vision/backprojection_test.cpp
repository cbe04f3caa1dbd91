#include "vision/backprojection.hpp"

#include <gtest/gtest.h>

#include "opencv2/imgproc.hpp"

namespace argus::vision {
namespace {

TEST(backprojection, ratio_histogram_is_t_over_i_clipped_to_one) {
  color_histogram target(histogram_bins{2, 1, 1});
  color_histogram image(histogram_bins{2, 1, 1});
  target.counts()[0] = 10;
  target.counts()[1] = 5;
  image.counts()[0] = 40;
  image.counts()[1] = 0;  // R = 0 where I = 0
  auto r = ratio_histogram(target, image);
  EXPECT_FLOAT_EQ(r[0], 0.25f);
  EXPECT_FLOAT_EQ(r[1], 0.0f);
  image.counts()[0] = 4;  // T > I: clipped to 1
  EXPECT_FLOAT_EQ(ratio_histogram(target, image)[0], 1.0f);
  // Rescaling T to an expected area of 3 pixels: 10 -> 2, so R = 2 / 4.
  EXPECT_FLOAT_EQ(ratio_histogram(target, image, 3.0)[0], 0.5f);
}

TEST(backprojection, emphasises_the_target_colours) {
  cv::Mat image(60, 80, CV_8UC3, cv::Scalar(30, 140, 30));  // green background
  cv::rectangle(image, cv::Rect(10, 10, 10, 30), cv::Scalar(0, 0, 220), cv::FILLED);  // red
  cv::rectangle(image, cv::Rect(50, 10, 10, 30), cv::Scalar(220, 0, 0), cv::FILLED);  // blue
  auto target = color_histogram::of_region(image, cv::Rect(10, 10, 10, 30));
  auto result = backproject_target(image, target);
  ASSERT_EQ(result.backprojection.type(), CV_32F);
  EXPECT_FLOAT_EQ(result.backprojection.at<float>(20, 15), 1.0f);  // red: T = I
  EXPECT_FLOAT_EQ(result.backprojection.at<float>(20, 55), 0.0f);  // blue: not in T
  EXPECT_FLOAT_EQ(result.backprojection.at<float>(50, 40), 0.0f);  // green: not in T
  // B(x, y) = R(map(c(x, y))) for every pixel.
  auto ratio = ratio_histogram(target, color_histogram::of_image(image));
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x)
      ASSERT_EQ(result.backprojection.at<float>(y, x),
                ratio[result.bin_indices.at<std::uint16_t>(y, x)]);
}

}  // namespace
}  // namespace argus::vision
