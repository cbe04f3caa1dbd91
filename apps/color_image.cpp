#include "apps/color_image.hpp"

#include <iostream>

#include "fmt/format.h"
#include "opencv2/imgcodecs.hpp"

namespace argus::apps {
namespace {

// Whether every pixel has B = G = R (grey-scale files come back so from IMREAD_COLOR).
bool is_grey(const cv::Mat& bgr) {
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; ++x)
      if (row[x][0] != row[x][1] || row[x][1] != row[x][2]) return false;
  }
  return true;
}

}  // namespace

std::optional<cv::Mat> read_color_image(const std::string& command, const std::string& option,
                                        const std::string& path) {
  cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) {
    std::cerr << fmt::format("{}: {}: cannot read an image from '{}'\n", command, option, path);
    return std::nullopt;
  }
  if (static_cast<long long>(image.cols) * image.rows > max_image_pixels) {
    std::cerr << fmt::format(
        "{}: {}: '{}' is {}x{} pixels, more than the {} ({}x{}) this command handles; scale it "
        "down\n",
        command, option, path, image.cols, image.rows, max_image_pixels, 3840, 2160);
    return std::nullopt;
  }
  if (is_grey(image)) {
    std::cerr << fmt::format(
        "{}: {}: '{}' is grey-scale; colour indexing needs a colour image (it bins hue and "
        "saturation, which grey pixels do not have)\n",
        command, option, path);
    return std::nullopt;
  }
  return image;
}

}  // namespace argus::apps
