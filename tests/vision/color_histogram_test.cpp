#include "vision/color_histogram.hpp"

#include <gtest/gtest.h>

#include "opencv2/imgproc.hpp"

namespace argus::vision {
namespace {

cv::Mat two_colour_image() {
  cv::Mat image(40, 30, CV_8UC3, cv::Scalar(200, 40, 40));                          // blue
  cv::rectangle(image, cv::Rect(0, 0, 30, 10), cv::Scalar(0, 0, 220), cv::FILLED);  // red
  return image;
}

TEST(color_histogram, default_bins_are_8_8_4) {
  color_histogram h;
  EXPECT_EQ(h.bins(), (histogram_bins{8, 8, 4}));
  EXPECT_EQ(h.counts().size(), 256u);
  EXPECT_EQ(h.total(), 0.0);
}

TEST(color_histogram, counts_pixels_into_hsv_bins) {
  auto image = two_colour_image();
  auto h = color_histogram::of_image(image);
  EXPECT_EQ(h.total(), 40.0 * 30.0);
  // Pure red: H = 0, S = 255, V = 220 -> bin (0 * 8 + 7) * 4 + 3.
  EXPECT_EQ(h[7 * 4 + 3], 300.0f);
  auto n = h.normalized();
  EXPECT_NEAR(n.total(), 1.0, 1e-6);
  EXPECT_NEAR(n[7 * 4 + 3], 0.25, 1e-6);
}

TEST(color_histogram, mask_and_region_select_pixels) {
  auto image = two_colour_image();
  cv::Mat mask = cv::Mat::zeros(image.size(), CV_8U);
  mask(cv::Rect(0, 0, 30, 10)).setTo(255);
  auto masked = color_histogram::of_image(image, {}, mask);
  auto region = color_histogram::of_region(image, cv::Rect(0, 0, 30, 10));
  EXPECT_EQ(masked, region);
  EXPECT_EQ(masked.total(), 300.0);
  EXPECT_EQ(color_histogram::of_region(image, cv::Rect(-10, -10, 5, 5)).total(), 0.0);
}

TEST(color_histogram, configurable_bins) {
  auto image = two_colour_image();
  auto h = color_histogram::of_image(image, {16, 4, 2});
  EXPECT_EQ(h.counts().size(), 128u);
  EXPECT_EQ(h.total(), 1200.0);
}

TEST(color_histogram, intersection_follows_swain_and_ballard) {
  auto image = two_colour_image();
  auto whole = color_histogram::of_image(image);
  auto red = color_histogram::of_region(image, cv::Rect(0, 0, 30, 10));
  auto blue = color_histogram::of_region(image, cv::Rect(0, 10, 30, 30));
  EXPECT_DOUBLE_EQ(intersection(red, red), 1.0);
  EXPECT_DOUBLE_EQ(intersection(red, blue), 0.0);
  EXPECT_DOUBLE_EQ(intersection(red, whole), 1.0);   // the whole image contains all the red
  EXPECT_DOUBLE_EQ(intersection(whole, red), 0.25);  // but only a quarter of the image is red
  EXPECT_NEAR(normalized_intersection(whole, red), 0.25, 1e-6);
  EXPECT_EQ(intersection(red, color_histogram(histogram_bins{4, 4, 4})), 0.0);
}

TEST(color_histogram, serialisation_round_trip) {
  cv::Mat image(64, 64, CV_8UC3);
  cv::randu(image, cv::Scalar::all(0), cv::Scalar::all(256));
  for (auto h : {color_histogram::of_image(image), color_histogram::of_image(image).normalized(),
                 color_histogram::of_image(image, {16, 4, 2}), color_histogram{}}) {
    auto bytes = h.serialize();
    auto back = color_histogram::deserialize(bytes);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(*back, h);
  }
  // A pedestrian-like signature is compact.
  auto bytes = color_histogram::of_image(two_colour_image()).serialize();
  EXPECT_EQ(bytes.size(), 8u + 2u * 6u);
}

TEST(color_histogram, rejects_corrupt_encodings) {
  auto bytes = color_histogram::of_image(two_colour_image()).serialize();
  EXPECT_FALSE(color_histogram::deserialize({}).has_value());
  auto truncated = bytes;
  truncated.pop_back();
  EXPECT_FALSE(color_histogram::deserialize(truncated).has_value());
  auto bad_magic = bytes;
  bad_magic[0] = 'X';
  EXPECT_FALSE(color_histogram::deserialize(bad_magic).has_value());
  auto bad_index = bytes;
  bad_index[8] = 0xff;
  bad_index[9] = 0xff;
  EXPECT_FALSE(color_histogram::deserialize(bad_index).has_value());
  auto zero_bins = bytes;
  zero_bins[3] = 0;
  EXPECT_FALSE(color_histogram::deserialize(zero_bins).has_value());
}

// The one-pass bin map and whole-image histogram equal the two-pass ones, for odd widths
// (the eight-pixel loop's tail) and other bin counts.
TEST(color_histogram, one_pass_bin_map_and_histogram_match) {
  cv::RNG rng(11);
  for (const cv::Size size : {cv::Size(320, 240), cv::Size(37, 5), cv::Size(3, 2)})
    for (const histogram_bins bins : {histogram_bins{}, histogram_bins{16, 4, 3}}) {
      cv::Mat image(size, CV_8UC3);
      rng.fill(image, cv::RNG::UNIFORM, 0, 256);
      cv::Mat indices(1, 1, CV_16U);  // a buffer of the wrong size is replaced
      const auto histogram = bin_index_image(image, bins, indices);
      EXPECT_EQ(cv::norm(indices, bin_index_image(image, bins), cv::NORM_INF), 0.0);
      EXPECT_EQ(histogram, color_histogram::of_bin_indices(
                               indices, cv::Rect(0, 0, size.width, size.height), bins));
    }
}

}  // namespace
}  // namespace argus::vision
