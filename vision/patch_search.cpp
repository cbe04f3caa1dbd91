#include "vision/patch_search.hpp"

#include "vision/backprojection.hpp"

namespace argus::vision {

std::vector<localized_region> find_patch(const cv::Mat& image, const cv::Mat& patch,
                                         const localizer_settings& settings) {
  const auto target = color_histogram::of_image(patch);
  const auto bp = backproject_target(image, target);
  multiscale_localizer localizer(settings);
  return localizer.localize(bp.backprojection, histogram_scorer(bp.bin_indices, target));
}

}  // namespace argus::vision
