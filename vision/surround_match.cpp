#include "vision/surround_match.hpp"

#include <algorithm>

namespace argus::vision {

namespace {

/// The ring's outer edge about `inner`, clipped to `image`.
cv::Rect ring_outer(const cv::Rect& inner, const cv::Rect& image) {
  const int dx = std::max(2, inner.width / 2);
  const int dy = std::max(2, inner.height / 4);
  return cv::Rect(inner.x - dx, inner.y - dy, inner.width + 2 * dx, inner.height + 2 * dy) & image;
}

}  // namespace

double surround_match(const cv::Mat& bin_indices, const cv::Rect& box, const histogram_bins& bins) {
  const cv::Rect image(0, 0, bin_indices.cols, bin_indices.rows);
  const auto inner = box & image;
  if (inner.empty()) return 0.0;
  const auto outer = ring_outer(inner, image);
  const auto figure = color_histogram::of_bin_indices(bin_indices, inner, bins);
  auto ring = color_histogram::of_bin_indices(bin_indices, outer, bins);
  for (std::size_t i = 0; i < ring.counts().size(); ++i) ring.counts()[i] -= figure[i];
  if (ring.total() <= 0.0) return 0.0;
  return normalized_intersection(figure, ring);
}

std::array<double, 4> surround_side_matches(const cv::Mat& bin_indices, const cv::Rect& box,
                                            const histogram_bins& bins) {
  std::array<double, 4> out{-1.0, -1.0, -1.0, -1.0};
  const cv::Rect image(0, 0, bin_indices.cols, bin_indices.rows);
  const auto inner = box & image;
  if (inner.empty()) return out;
  const auto outer = ring_outer(inner, image);
  const std::array<cv::Rect, 4> sides{
      cv::Rect(outer.x, inner.y, inner.x - outer.x, inner.height),
      cv::Rect(inner.br().x, inner.y, outer.br().x - inner.br().x, inner.height),
      cv::Rect(outer.x, outer.y, outer.width, inner.y - outer.y),
      cv::Rect(outer.x, inner.br().y, outer.width, outer.br().y - inner.br().y)};
  const auto figure = color_histogram::of_bin_indices(bin_indices, inner, bins);
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (sides[i].empty()) continue;
    const auto side = color_histogram::of_bin_indices(bin_indices, sides[i], bins);
    if (side.total() > 0.0) out[i] = normalized_intersection(figure, side);
  }
  return out;
}

int sides_matching(const std::array<double, 4>& sides, double threshold) {
  return static_cast<int>(
      std::count_if(sides.begin(), sides.end(), [&](double m) { return m > threshold; }));
}

bool background_by_sides(const std::array<double, 4>& sides, double threshold, int required) {
  const auto inside = static_cast<int>(
      std::count_if(sides.begin(), sides.end(), [](double m) { return m >= 0.0; }));
  return inside > 0 && sides_matching(sides, threshold) >= std::min(required, inside);
}

}  // namespace argus::vision
