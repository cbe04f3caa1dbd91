#pragma once

// Histogram backprojection (Section III-B; Swain and Ballard [45]).

#include <optional>

#include "opencv2/core.hpp"
#include "vision/color_histogram.hpp"

namespace argus::vision {

/// The ratio histogram R(i) = T(i) / I(i), with R(i) = 0 where I(i) = 0 (Section III-B),
/// clipped to 1 as Swain and Ballard do: min(T(i) / I(i), 1). The clip keeps a colour that the
/// target owns from outweighing the others just because it is rare in the image; it is
/// exact when T counts the target at its size in the image, since then T(i) <= I(i).
/// `target_pixels` rescales T to that many pixels first (the expected area of the target in
/// the image); nullopt uses T's raw counts. Returns an empty histogram on mismatched bins.
color_histogram ratio_histogram(const color_histogram& target, const color_histogram& image,
                                std::optional<double> target_pixels = std::nullopt);

/// Backprojects a ratio histogram: B(x, y) = R(map(c(x, y))) (Section III-B), where
/// `bin_indices` is map(c(x, y)) from bin_index_image(). Returns a CV_32F image.
cv::Mat backproject(const cv::Mat& bin_indices, const color_histogram& ratio);

/// The whole step for a BGR frame: map(c), the image histogram I, R = ratio_histogram(T, I,
/// target_pixels) and B. Also returns the bin-index image, which the localiser's acceptance
/// test (Fig. 9, step 5) reuses.
struct backprojection_result {
  /// B(x, y), CV_32F, values in [0, 1].
  cv::Mat backprojection;
  /// map(c(x, y)), CV_16U.
  cv::Mat bin_indices;
};

/// Computes B for `target` in the BGR frame `bgr` (see backprojection_result).
backprojection_result backproject_target(const cv::Mat& bgr, const color_histogram& target,
                                         std::optional<double> target_pixels = std::nullopt);

}  // namespace argus::vision
