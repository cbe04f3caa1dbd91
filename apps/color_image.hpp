#pragma once

// Reading the colour images that colour indexing (vision/color_histogram.hpp) works on, with
// the limits a command states instead of failing late or silently.

#include <optional>
#include <string>

#include "opencv2/core.hpp"

namespace argus::apps {

/// The most pixels an input image may have: 3840 x 2160 (4K UHD). The localiser holds about
/// 40 bytes per pixel (integral images in double, the summed response), some 330 MB at this
/// size; a 6144 x 4608 photograph would take over a gigabyte.
inline constexpr long long max_image_pixels = 3840LL * 2160LL;

/// The BGR image in `path` for `option` of `command`; on failure prints why (unreadable, too
/// large, grey-scale: hue and saturation, which colour indexing bins, are undefined there) and
/// returns nullopt.
std::optional<cv::Mat> read_color_image(const std::string& command, const std::string& option,
                                        const std::string& path);

}  // namespace argus::apps
