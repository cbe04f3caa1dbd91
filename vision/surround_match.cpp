#include "vision/surround_match.hpp"

#include <algorithm>

namespace argus::vision {

double surround_match(const cv::Mat& bin_indices, const cv::Rect& box, const histogram_bins& bins) {
  const cv::Rect image(0, 0, bin_indices.cols, bin_indices.rows);
  const auto inner = box & image;
  if (inner.empty()) return 0.0;
  const int dx = std::max(2, inner.width / 2);
  const int dy = std::max(2, inner.height / 4);
  const auto outer =
      cv::Rect(inner.x - dx, inner.y - dy, inner.width + 2 * dx, inner.height + 2 * dy) & image;
  const auto figure = color_histogram::of_bin_indices(bin_indices, inner, bins);
  auto ring = color_histogram::of_bin_indices(bin_indices, outer, bins);
  for (std::size_t i = 0; i < ring.counts().size(); ++i) ring.counts()[i] -= figure[i];
  if (ring.total() <= 0.0) return 0.0;
  return normalized_intersection(figure, ring);
}

}  // namespace argus::vision
