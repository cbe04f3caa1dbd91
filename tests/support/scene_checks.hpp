#pragma once

// Whether a picture shows a rendered scene: not black, not one flat colour. A failed render
// becomes a black tile (with at most a camera label on it), which these checks reject.

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace argus::test_support {

/// Brightness statistics of a BGR picture.
struct scene_statistics {
  double mean = 0.0;          // grey level, 0..255
  double stddev = 0.0;        // of the grey level
  double lit_fraction = 0.0;  // pixels brighter than grey 25
};

/// The statistics of `bgr`.
inline scene_statistics statistics_of(const cv::Mat& bgr) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::Scalar mean, stddev;
  cv::meanStdDev(grey, mean, stddev);
  const double lit =
      static_cast<double>(cv::countNonZero(grey > 25)) / static_cast<double>(grey.total());
  return {mean[0], stddev[0], lit};
}

/// A rendered station view: mostly lit, with some contrast (floor, walls, people).
inline bool shows_a_scene(const scene_statistics& s) {
  return s.mean >= 30.0 && s.stddev >= 6.0 && s.lit_fraction >= 0.5;
}

}  // namespace argus::test_support
