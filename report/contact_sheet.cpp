#include "report/contact_sheet.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "report/drawing.hpp"

namespace argus::report {

namespace {

using layout = contact_sheet_layout;

constexpr double caption_scale = 0.4;

int block_height_px() {
  return layout::tile_height_px + layout::caption_lines * layout::line_px + 4;
}

// `text` cut with "..." to fit `width_px`.
std::string fitted(std::string text, int width_px) {
  if (text_width(text, caption_scale) <= width_px) return text;
  while (!text.empty() && text_width(text + "...", caption_scale) > width_px) text.pop_back();
  return text + "...";
}

// `image` scaled into `area` of `sheet`, aspect kept, centred on a dark ground.
void place(cv::Mat& sheet, const cv::Mat& image, const cv::Rect& area) {
  sheet(area).setTo(cv::Scalar(40, 40, 40));
  if (image.empty()) return;
  const double scale = std::min(static_cast<double>(area.width) / image.cols,
                                static_cast<double>(area.height) / image.rows);
  const cv::Size size(std::max(1, static_cast<int>(image.cols * scale)),
                      std::max(1, static_cast<int>(image.rows * scale)));
  cv::Mat scaled;
  cv::resize(image, scaled, size, 0.0, 0.0, cv::INTER_AREA);
  scaled.copyTo(sheet(cv::Rect(area.x + (area.width - size.width) / 2,
                               area.y + (area.height - size.height) / 2, size.width, size.height)));
}

}  // namespace

contact_sheet_layout contact_sheet_layout::for_tiles(std::size_t tiles) {
  contact_sheet_layout out;
  const int n = static_cast<int>(std::max<std::size_t>(tiles, 1));
  out.columns = std::min(n, max_columns);
  out.rows = (n + out.columns - 1) / out.columns;
  return out;
}

cv::Size contact_sheet_layout::size() const {
  return {gap_px + columns * (tile_width_px + gap_px),
          title_px + rows * (block_height_px() + gap_px) + note_px};
}

cv::Rect contact_sheet_layout::tile(std::size_t k) const {
  const int i = static_cast<int>(k);
  return {gap_px + (i % columns) * (tile_width_px + gap_px),
          title_px + (i / columns) * (block_height_px() + gap_px), tile_width_px, tile_height_px};
}

cv::Mat render_contact_sheet(const std::vector<contact_sheet_tile>& tiles, const std::string& title,
                             const std::string& note) {
  const auto grid = layout::for_tiles(tiles.size());
  const auto size = grid.size();
  cv::Mat sheet(size, CV_8UC3, cv::Scalar(255, 255, 255));
  draw_text(sheet, fitted(title, size.width - 2 * layout::gap_px), {layout::gap_px, 20}, 0.5);
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const auto area = grid.tile(k);
    place(sheet, tiles[k].image, area);
    int y = area.y + area.height + layout::line_px;
    for (std::size_t line = 0;
         line < tiles[k].caption.size() && line < static_cast<std::size_t>(layout::caption_lines);
         ++line, y += layout::line_px)
      draw_text(sheet, fitted(tiles[k].caption[line], area.width), {area.x, y - 3}, caption_scale);
  }
  if (!note.empty())
    draw_text(sheet, fitted(note, size.width - 2 * layout::gap_px),
              {layout::gap_px, size.height - 8}, caption_scale);
  return sheet;
}

}  // namespace argus::report
