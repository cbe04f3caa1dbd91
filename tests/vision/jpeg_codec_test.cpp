#include "vision/jpeg_codec.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace argus::vision {
namespace {

// A frame like a camera's: a floor gradient, figures with sharp colour edges, and noise.
cv::Mat scene(int width, int height, int seed) {
  cv::Mat f(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      f.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<unsigned char>(120 + x % 40),
                                        static_cast<unsigned char>(110 + y % 30),
                                        static_cast<unsigned char>(100 + (x + y) % 50));
    }
  }
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  for (int k = 0; k < 12; ++k) {
    const cv::Point at(rng.uniform(0, width), rng.uniform(0, height));
    cv::rectangle(f, cv::Rect(at, cv::Size(rng.uniform(3, 30), rng.uniform(8, 90))),
                  cv::Scalar(rng.uniform(0, 256), rng.uniform(0, 256), rng.uniform(0, 256)),
                  cv::FILLED);
  }
  cv::Mat noise(f.size(), CV_8UC3);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 12);
  return f + noise;
}

// What the imaging model did before: OpenCV's own encoder and decoder.
std::vector<std::uint8_t> opencv_jpeg(const cv::Mat& bgr, int quality) {
  std::vector<std::uint8_t> bytes;
  if (!cv::imencode(".jpg", bgr, bytes, {cv::IMWRITE_JPEG_QUALITY, quality})) {
    throw std::runtime_error("cv::imencode failed");
  }
  return bytes;
}

TEST(jpeg_codec, writes_the_bytes_and_decodes_the_pixels_opencv_does) {
  int seed = 0;
  for (const cv::Size size : {cv::Size(640, 480), cv::Size(320, 240), cv::Size(323, 241),
                              cv::Size(17, 9), cv::Size(1, 1)}) {
    for (const int quality : {1, 30, 75, 95, 100}) {
      const cv::Mat frame = scene(size.width, size.height, ++seed);
      const auto expected = opencv_jpeg(frame, quality);
      std::vector<std::uint8_t> bytes;
      encode_jpeg(frame, quality, bytes);
      EXPECT_EQ(bytes, expected) << size << " at quality " << quality;
      const cv::Mat ours = decode_jpeg(expected);
      const cv::Mat theirs = cv::imdecode(expected, cv::IMREAD_COLOR);
      ASSERT_EQ(ours.size(), theirs.size());
      ASSERT_EQ(ours.type(), CV_8UC3);
      EXPECT_EQ(cv::norm(ours, theirs, cv::NORM_INF), 0.0) << size << " at quality " << quality;
    }
  }
}

TEST(jpeg_codec, encodes_a_region_of_a_larger_image_by_its_rows) {
  const cv::Mat frame = scene(200, 150, 3);
  const cv::Mat region = frame(cv::Rect(13, 7, 101, 77));
  ASSERT_FALSE(region.isContinuous());
  std::vector<std::uint8_t> bytes;
  encode_jpeg(region, 75, bytes);
  EXPECT_EQ(bytes, opencv_jpeg(region.clone(), 75));
}

TEST(jpeg_codec, clamps_the_quality_as_the_imaging_model_did) {
  const cv::Mat frame = scene(64, 48, 5);
  std::vector<std::uint8_t> low, lowest, high, highest;
  encode_jpeg(frame, -5, low);
  encode_jpeg(frame, 1, lowest);
  encode_jpeg(frame, 250, high);
  encode_jpeg(frame, 100, highest);
  EXPECT_EQ(low, lowest);
  EXPECT_EQ(high, highest);
  EXPECT_LT(lowest.size(), highest.size());
}

TEST(jpeg_codec, a_grey_jpeg_decodes_to_three_equal_channels) {
  cv::Mat grey(30, 40, CV_8UC1);
  cv::randu(grey, 0, 256);
  std::vector<std::uint8_t> bytes;
  ASSERT_TRUE(cv::imencode(".jpg", grey, bytes));
  const cv::Mat ours = decode_jpeg(bytes);
  EXPECT_EQ(cv::norm(ours, cv::imdecode(bytes, cv::IMREAD_COLOR), cv::NORM_INF), 0.0);
}

TEST(jpeg_codec, bad_input_is_an_exception_not_an_exit) {
  const std::vector<std::uint8_t> not_a_jpeg{'P', 'N', 'G', 0, 1, 2, 3};
  EXPECT_THROW(decode_jpeg(not_a_jpeg), std::runtime_error);
  EXPECT_THROW(decode_jpeg({}), std::runtime_error);
  // A JPEG cut short decodes what it has, as libjpeg does with a warning: the header must be
  // there, which a cut inside it is not.
  std::vector<std::uint8_t> bytes;
  encode_jpeg(scene(64, 48, 9), 75, bytes);
  EXPECT_THROW(decode_jpeg(std::span<const std::uint8_t>(bytes.data(), 40)), std::runtime_error);
  cv::Mat grey(8, 8, CV_8UC1, cv::Scalar(3));
  EXPECT_THROW(encode_jpeg(grey, 75, bytes), std::invalid_argument);
  EXPECT_THROW(encode_jpeg(cv::Mat(), 75, bytes), std::invalid_argument);
}

}  // namespace
}  // namespace argus::vision
