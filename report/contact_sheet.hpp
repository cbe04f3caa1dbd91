#pragma once

#include <cstddef>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace argus::report {

/// One frame of a contact sheet and the lines written under it.
struct contact_sheet_tile {
  cv::Mat image;
  std::vector<std::string> caption;
};

/// Where a contact sheet puts its title, its tiles and its note: up to six tiles a row, each
/// frame scaled into tile_width_px x tile_height_px (aspect kept) over caption_lines lines.
struct contact_sheet_layout {
  static constexpr int tile_width_px = 240;
  static constexpr int tile_height_px = 180;
  static constexpr int caption_lines = 3;
  static constexpr int line_px = 15;
  static constexpr int gap_px = 8;
  static constexpr int title_px = 30;
  static constexpr int note_px = 24;
  static constexpr int max_columns = 6;

  int columns = 1;
  int rows = 1;

  /// The grid for `tiles` tiles.
  static contact_sheet_layout for_tiles(std::size_t tiles);

  /// Size of the whole sheet.
  cv::Size size() const;

  /// Where frame `k`'s tile (image area, without its caption) goes.
  cv::Rect tile(std::size_t k) const;
};

/// The contact sheet (paper Fig. 18): `title` on top, the tiles in reading order, each frame
/// scaled to fit its tile with its caption under it (lines too wide are cut with "..."), and
/// `note` at the bottom when not empty (e.g. how many frames the cap left out). White
/// background, BGR.
cv::Mat render_contact_sheet(const std::vector<contact_sheet_tile>& tiles, const std::string& title,
                             const std::string& note);

}  // namespace argus::report
