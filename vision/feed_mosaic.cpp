#include "vision/feed_mosaic.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fmt/format.h"
#include "opencv2/imgproc.hpp"

namespace argus::vision {
namespace {

constexpr int gap_px = 2;

}  // namespace

feed_mosaic_layout feed_mosaic_layout::for_feeds(std::size_t cameras, int tile_width_px,
                                                 int tile_height_px) {
  const int n = static_cast<int>(std::max<std::size_t>(cameras, 1));
  feed_mosaic_layout layout;
  layout.columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  layout.rows = (n + layout.columns - 1) / layout.columns;
  layout.tile_width_px = tile_width_px;
  layout.tile_height_px = tile_height_px;
  return layout;
}

cv::Size feed_mosaic_layout::size() const {
  return {columns * tile_width_px + (columns - 1) * gap_px,
          rows * tile_height_px + (rows - 1) * gap_px};
}

cv::Rect feed_mosaic_layout::tile(std::size_t k) const {
  const int i = static_cast<int>(k);
  return {(i % columns) * (tile_width_px + gap_px), (i / columns) * (tile_height_px + gap_px),
          tile_width_px, tile_height_px};
}

void label_feed(cv::Mat& tile, int camera_id) {
  const std::string text = fmt::format("C{}", camera_id);
  const double scale = std::max(0.4, tile.cols / 640.0);
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline);
  cv::rectangle(tile, {0, 0}, {size.width + 8, size.height + baseline + 6}, {20, 20, 20},
                cv::FILLED);
  cv::putText(tile, text, {4, size.height + 3}, cv::FONT_HERSHEY_SIMPLEX, scale, {255, 255, 255}, 1,
              cv::LINE_AA);
}

void draw_feed_label(cv::Mat& image, const std::string& text, cv::Point at,
                     const cv::Scalar& colour) {
  const double scale = std::max(0.4, image.cols / 640.0);
  int baseline = 0;
  const auto size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline);
  at.x = std::clamp(at.x, 0, std::max(0, image.cols - size.width - 4));
  at.y = std::clamp(at.y, size.height + 4, std::max(size.height + 4, image.rows - baseline));
  cv::rectangle(image, {at.x, at.y - size.height - 3}, {at.x + size.width + 4, at.y + baseline},
                {20, 20, 20}, cv::FILLED);
  cv::putText(image, text, {at.x + 2, at.y - 1}, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1,
              cv::LINE_AA);
}

void mark_failed_feed(cv::Mat& image) {
  cv::Mat grey;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(grey, -1, 0.6, 30.0);  // paler: a frame of the past
  cv::cvtColor(grey, image, cv::COLOR_GRAY2BGR);
  const cv::Scalar red(40, 40, 230);
  cv::line(image, {0, 0}, {image.cols - 1, image.rows - 1}, red, 2, cv::LINE_AA);
  cv::line(image, {image.cols - 1, 0}, {0, image.rows - 1}, red, 2, cv::LINE_AA);
  draw_feed_label(image, "FAILED", {image.cols / 2 - 30, image.rows / 2}, red);
}

}  // namespace argus::vision
