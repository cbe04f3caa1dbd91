#pragma once

// Finding a target patch's colours in an image (`argus vision localize`): colour indexing
// with the multiscale localiser of Fig. 9 at given kernel sizes.

#include <vector>

#include "opencv2/core.hpp"
#include "vision/multiscale_localizer.hpp"

namespace argus::vision {

/// Every region of the BGR `image` whose colours match the BGR `patch`: the patch's histogram
/// T backprojected through R = min(T / I, 1) (T at the patch's own size), localised at kernel
/// sizes `settings.scales` (one size: Swain and Ballard's single-scale search) and accepted by
/// histogram intersection > rho, at most max_regions, in the order found.
std::vector<localized_region> find_patch(const cv::Mat& image, const cv::Mat& patch,
                                         const localizer_settings& settings);

}  // namespace argus::vision
