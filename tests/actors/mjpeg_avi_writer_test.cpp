// The run's mosaic video (actors/mjpeg_avi_writer): what OpenCV's reader (FFmpeg) gets back
// from it, for an odd frame size and a rate that is not a whole number.
#include "actors/mjpeg_avi_writer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

namespace argus::actors {
namespace {

TEST(mjpeg_avi_writer, frames_size_and_rate_read_back) {
  const auto file = std::filesystem::temp_directory_path() / "argus_mjpeg_avi_writer_test.avi";
  const cv::Size size(33, 17);
  {
    mjpeg_avi_writer writer(file, 7.5, size);
    for (int k = 0; k < 3; ++k)
      writer.write(cv::Mat(size, CV_8UC3, cv::Scalar(40 * k, 200 - 40 * k, 90)));
  }
  cv::VideoCapture video(file.string());
  ASSERT_TRUE(video.isOpened());
  EXPECT_NEAR(video.get(cv::CAP_PROP_FPS), 7.5, 1e-3);
  int frames = 0;
  for (cv::Mat frame; video.read(frame); ++frames) {
    ASSERT_EQ(frame.size(), size);
    // Flat colours survive JPEG within a few levels.
    const cv::Scalar mean = cv::mean(frame);
    EXPECT_NEAR(mean[0], 40 * frames, 4.0);
    EXPECT_NEAR(mean[1], 200 - 40 * frames, 4.0);
  }
  EXPECT_EQ(frames, 3);
  std::filesystem::remove(file);
}

TEST(mjpeg_avi_writer, refuses_a_file_it_cannot_write) {
  EXPECT_THROW(mjpeg_avi_writer("/nonexistent/dir/x.avi", 15.0, {16, 16}), std::runtime_error);
}

}  // namespace
}  // namespace argus::actors
