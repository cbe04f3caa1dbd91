#include "vision/backprojection.hpp"

#include <algorithm>

namespace argus::vision {

color_histogram ratio_histogram(const color_histogram& target, const color_histogram& image,
                                std::optional<double> target_pixels) {
  color_histogram ratio(target.bins());
  if (target.bins() != image.bins()) return ratio;
  double scale = 1.0;
  if (target_pixels) {
    double total = target.total();
    scale = total > 0.0 ? *target_pixels / total : 0.0;
  }
  auto t = target.counts();
  auto i = image.counts();
  auto r = ratio.counts();
  for (std::size_t k = 0; k < r.size(); ++k)
    r[k] = i[k] > 0.0f ? static_cast<float>(std::min(scale * t[k] / i[k], 1.0)) : 0.0f;
  return ratio;
}

cv::Mat backproject(const cv::Mat& bin_indices, const color_histogram& ratio) {
  CV_Assert(bin_indices.type() == CV_16U);
  const float* table = ratio.counts().data();
  const auto bin_count = ratio.counts().size();
  cv::Mat result(bin_indices.size(), CV_32F);
  for (int y = 0; y < bin_indices.rows; ++y) {
    const auto* in = bin_indices.ptr<std::uint16_t>(y);
    auto* out = result.ptr<float>(y);
    for (int x = 0; x < bin_indices.cols; ++x) out[x] = in[x] < bin_count ? table[in[x]] : 0.0f;
  }
  return result;
}

backprojection_result backproject_target(const cv::Mat& bgr, const color_histogram& target,
                                         std::optional<double> target_pixels) {
  backprojection_result result;
  const auto image = bin_index_image(bgr, target.bins(), result.bin_indices);
  result.backprojection =
      backproject(result.bin_indices, ratio_histogram(target, image, target_pixels));
  return result;
}

}  // namespace argus::vision
