#pragma once

// Colour histograms in HSV for colour indexing (Section III-B; Swain and Ballard [45]).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "opencv2/core.hpp"

namespace argus::vision {

/// How many bins each HSV channel is split into. The default, 8 x 8 x 4 = 256 bins, follows
/// the paper's advice to index hue and saturation finely and brightness coarsely, which keeps
/// the signature tolerant of illumination changes (Section III-B). Each count is in [1, 255].
struct histogram_bins {
  int hue = 8;
  int saturation = 8;
  int value = 4;
  /// The number of bins, hue x saturation x value.
  int count() const noexcept { return hue * saturation * value; }
  friend bool operator==(const histogram_bins&, const histogram_bins&) = default;
};

/// The bin of every pixel of a BGR image: map(c(x, y)) of Section III-B, as a CV_16U image.
/// Hue, saturation and value are OpenCV's 8-bit HSV (H in [0, 180), S and V in [0, 256)),
/// each split into equal-width bins; bin = (h_bin * saturation + s_bin) * value + v_bin.
cv::Mat bin_index_image(const cv::Mat& bgr, const histogram_bins& bins = {});

/// An HSV colour histogram: raw counts (one per pixel) or normalised to sum 1. This is the
/// appearance signature of a pedestrian, the one a camera sends in a `queryrelevance` message.
class color_histogram {
 public:
  /// An empty histogram with the default 8 x 8 x 4 bins.
  color_histogram();

  /// An empty histogram with `bins`.
  explicit color_histogram(const histogram_bins& bins);

  /// The histogram of a BGR image (CV_8UC3), counting only pixels where `mask` (CV_8U, same
  /// size) is non-zero when a mask is given.
  static color_histogram of_image(const cv::Mat& bgr, const histogram_bins& bins = {},
                                  const cv::Mat& mask = {});

  /// The histogram of `region` of a BGR image (clipped to the image).
  static color_histogram of_region(const cv::Mat& bgr, const cv::Rect& region,
                                   const histogram_bins& bins = {});

  /// The histogram of `region` of a bin-index image made by bin_index_image() with `bins`.
  static color_histogram of_bin_indices(const cv::Mat& bin_indices, const cv::Rect& region,
                                        const histogram_bins& bins = {});

  /// The bins this histogram uses.
  const histogram_bins& bins() const noexcept { return bins_; }

  /// The count (or fraction) in each bin.
  std::span<const float> counts() const noexcept { return counts_; }

  /// Mutable access to the counts, e.g. to build a histogram by hand.
  std::span<float> counts() noexcept { return counts_; }

  /// The count in bin `i`.
  float operator[](std::size_t i) const noexcept { return counts_[i]; }

  /// The sum of all bins.
  double total() const noexcept;

  /// This histogram scaled to sum 1 (unchanged if it is empty).
  color_histogram normalized() const;

  /// A compact byte encoding: "AH", a version byte, the three bin counts, the number of
  /// non-empty bins (uint16) and, per non-empty bin, its index (uint16) and count (float32),
  /// all little-endian. A pedestrian's histogram is sparse, so this is usually < 300 bytes.
  std::vector<std::uint8_t> serialize() const;

  /// Decodes serialize()'s output; nullopt if `bytes` is not a valid encoding.
  static std::optional<color_histogram> deserialize(std::span<const std::uint8_t> bytes);

  friend bool operator==(const color_histogram&, const color_histogram&) = default;

 private:
  histogram_bins bins_;
  std::vector<float> counts_;
};

/// Swain and Ballard's histogram intersection, normalised by the target:
/// sum_i min(T(i), H(i)) / sum_i T(i), in [0, 1] (Fig. 9, step 5). Both histograms must have
/// the same bins and comparable totals; normalise them first to compare regions of different
/// sizes. Returns 0 for an empty target or mismatched bins.
double intersection(const color_histogram& target, const color_histogram& candidate);

/// Intersection of the normalised histograms: the scale-free match score used to accept a
/// region (Fig. 9, step 5), since under zoom the region and the target differ in pixel count.
double normalized_intersection(const color_histogram& target, const color_histogram& candidate);

/// bin_index_image() into `indices` (its buffer reused when it fits), returning in the same
/// pass the histogram of the whole image (equal to color_histogram::of_bin_indices() on it).
color_histogram bin_index_image(const cv::Mat& bgr, const histogram_bins& bins, cv::Mat& indices);

}  // namespace argus::vision
