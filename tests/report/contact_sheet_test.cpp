#include "report/contact_sheet.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace argus::report {
namespace {

using layout = contact_sheet_layout;

TEST(contact_sheet, up_to_six_tiles_a_row) {
  EXPECT_EQ(layout::for_tiles(1).columns, 1);
  EXPECT_EQ(layout::for_tiles(4).columns, 4);
  EXPECT_EQ(layout::for_tiles(6).rows, 1);
  EXPECT_EQ(layout::for_tiles(7).columns, 6);
  EXPECT_EQ(layout::for_tiles(7).rows, 2);
  EXPECT_EQ(layout::for_tiles(48).rows, 8);
}

TEST(contact_sheet, each_frame_fills_its_tile_with_its_caption_under_it) {
  // Seven flat frames of distinct colours, 4:3 like the cameras'.
  std::vector<contact_sheet_tile> tiles;
  for (int k = 0; k < 7; ++k)
    tiles.push_back({cv::Mat(240, 320, CV_8UC3, cv::Scalar(30 * k, 200 - 20 * k, 100)),
                     {"16.00 s  task start  task 0", "camera 7",
                      "a caption far too long to fit "
                      "in a tile of the sheet at all"}});
  const auto sheet = render_contact_sheet(tiles, "title", "3 frames left out");
  const auto grid = layout::for_tiles(7);
  ASSERT_EQ(sheet.size(), grid.size());
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const auto area = grid.tile(k);
    const cv::Point centre(area.x + area.width / 2, area.y + area.height / 2);
    const auto got = sheet.at<cv::Vec3b>(centre);
    const auto want = tiles[k].image.at<cv::Vec3b>(120, 160);
    EXPECT_EQ(got, want) << "tile " << k;
    // The caption is written (dark ink) below the tile, within the tile's width.
    const cv::Rect caption(area.x, area.y + area.height, area.width,
                           layout::caption_lines * layout::line_px);
    cv::Mat grey;
    cv::cvtColor(sheet(caption), grey, cv::COLOR_BGR2GRAY);
    EXPECT_GT(cv::countNonZero(grey < 128), 50) << "caption of tile " << k;
  }
  // Beyond the last tile of the second row: white.
  const auto empty = grid.tile(7);
  EXPECT_EQ(sheet.at<cv::Vec3b>(empty.y + 10, empty.x + 10), cv::Vec3b(255, 255, 255));
}

}  // namespace
}  // namespace argus::report
