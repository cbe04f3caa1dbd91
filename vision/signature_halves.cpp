#include "vision/signature_halves.hpp"

#include <algorithm>

#include "vision/signature_update.hpp"

namespace argus::vision {

box_halves halves_of(const cv::Rect& box) {
  if (box.empty()) return {};
  const int middle = box.y + std::max(1, box.height / 2);
  const int top = std::min(box.y + box.height / 8, middle - 1);
  const int bottom = std::max(box.y + box.height, middle + 1);
  return {cv::Rect(box.x, top, box.width, middle - top),
          cv::Rect(box.x, middle, box.width, bottom - middle)};
}

signature_halves halves_in(const cv::Mat& bin_indices, const cv::Rect& box,
                           const histogram_bins& bins) {
  const auto halves = halves_of(box);
  return {color_histogram::of_bin_indices(bin_indices, halves.upper, bins).normalized(),
          color_histogram::of_bin_indices(bin_indices, halves.lower, bins).normalized()};
}

histogram_bins halves_comparison_bins(const histogram_bins& signature_bins) {
  return {signature_bins.hue, std::max(1, signature_bins.saturation / 2), 1};
}

color_histogram merged_into(const color_histogram& histogram, const histogram_bins& bins) {
  const auto& fine = histogram.bins();
  color_histogram coarse(bins);
  for (int i = 0; i < fine.count(); ++i) {
    const int h = i / (fine.saturation * fine.value);
    const int s = (i / fine.value) % fine.saturation;
    const int v = i % fine.value;
    const int to =
        ((h * bins.hue / fine.hue) * bins.saturation + s * bins.saturation / fine.saturation) *
            bins.value +
        v * bins.value / fine.value;
    coarse.counts()[static_cast<std::size_t>(to)] += histogram[static_cast<std::size_t>(i)];
  }
  return coarse;
}

signature_halves blended_halves(const signature_halves& signature, const signature_halves& seen,
                                double own_weight) {
  return {blended(signature.upper, seen.upper, own_weight),
          blended(signature.lower, seen.lower, own_weight)};
}

double halves_match(const signature_halves& model, const signature_halves& seen) {
  if (model.upper.total() <= 0.0 || model.lower.total() <= 0.0 || seen.upper.total() <= 0.0 ||
      seen.lower.total() <= 0.0)
    return 0.0;
  const auto bins = halves_comparison_bins(model.upper.bins());
  const auto match = [&](const color_histogram& a, const color_histogram& b) {
    return normalized_intersection(merged_into(a, bins), merged_into(b, bins));
  };
  return std::min(match(model.upper, seen.upper), match(model.lower, seen.lower));
}

}  // namespace argus::vision
