#pragma once

#include <cstddef>
#include <string>

#include "opencv2/core.hpp"

namespace argus::vision {

/// How camera feeds are tiled into one picture, like a monitor wall (paper Fig. 3): a
/// near-square grid in camera order, tiles 2 px apart. `argus feeds` and the run video share it.
struct feed_mosaic_layout {
  int columns = 1;
  int rows = 1;
  int tile_width_px = 0;
  int tile_height_px = 0;

  /// The grid for `cameras` feeds of `tile_width_px` x `tile_height_px`.
  static feed_mosaic_layout for_feeds(std::size_t cameras, int tile_width_px, int tile_height_px);

  /// Size of the whole picture.
  cv::Size size() const;

  /// Where feed number `k` goes.
  cv::Rect tile(std::size_t k) const;
};

/// Writes "C<id>" in the tile's top-left corner, white on a dark box, so a viewer can tell
/// which camera a feed comes from.
void label_feed(cv::Mat& tile, int camera_id);

/// Writes `text` in `colour` on a dark box with its baseline at `at`, kept inside the image.
void draw_feed_label(cv::Mat& image, const std::string& text, cv::Point at,
                     const cv::Scalar& colour);

/// A failed camera's frame: paler grey, crossed in red and labelled FAILED (the key frames of
/// feeds/ and the run video draw a crashed camera alike).
void mark_failed_feed(cv::Mat& image);

}  // namespace argus::vision
