#include "vision/signature_update.hpp"

#include <algorithm>
#include <cmath>

namespace argus::vision {

cv::Rect body_core(const cv::Rect& box, const signature_update_settings& settings) {
  const int width = std::max(1, static_cast<int>(std::lround(box.width * settings.core_width)));
  const int height = std::max(1, static_cast<int>(std::lround(box.height * settings.core_height)));
  return {box.x + (box.width - width) / 2, box.y + (box.height - height) / 2, width, height};
}

bool model_due(int confirmed_frames, int box_height_px, int model_height_px,
               const signature_update_settings& settings) {
  if (confirmed_frames < settings.confirm_frames || box_height_px <= 0) return false;
  if (model_height_px <= 0) return true;
  const double ratio = static_cast<double>(box_height_px) / model_height_px;
  return ratio >= settings.height_change || ratio <= 1.0 / settings.height_change;
}

color_histogram blended(const color_histogram& signature, const color_histogram& own,
                        double own_weight) {
  const auto given = signature.normalized();
  const auto seen = own.normalized();
  if (seen.total() <= 0.0 || seen.bins() != given.bins()) return given;
  color_histogram model(given.bins());
  auto counts = model.counts();
  for (std::size_t i = 0; i < counts.size(); ++i)
    counts[i] = static_cast<float>((1.0 - own_weight) * given[i] + own_weight * seen[i]);
  return model.normalized();
}

color_histogram blended_model(const color_histogram& signature, const cv::Mat& bin_indices,
                              const cv::Rect& box, const signature_update_settings& settings) {
  const auto core = body_core(box, settings) & cv::Rect(0, 0, bin_indices.cols, bin_indices.rows);
  if (core.empty()) return signature.normalized();
  return blended(signature, color_histogram::of_bin_indices(bin_indices, core, signature.bins()),
                 settings.own_weight);
}

}  // namespace argus::vision
