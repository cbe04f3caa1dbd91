// Finding people again on real video (tests/data/vtest, frames of OpenCV's vtest.avi with
// hand-checked boxes; bench/localization_bench reports the full table): a patch of a person
// cut from one frame, the whole frame searched 5, 15 and 30 frames later, a hit when the first
// box overlaps her true box by IoU >= 0.3. Floors a little under what the default measured
// (0.83 of 65 searches; a patch-sized single scale 0.80, the paper's scales 0.00).
#include <gtest/gtest.h>

#include "tests/support/real_video_searches.hpp"
#include "vision/patch_search.hpp"

namespace argus::vision {
namespace {

double hit_rate(const test_support::real_video_set& set, const scale_settings& scales) {
  int hits = 0;
  for (const auto& s : set.searches) {
    const cv::Mat& frame = set.frames.at(s.to);
    const auto settings =
        localizer_settings_for(scales, cv::Size2d(s.patch_box.size()), frame.rows, 0.5, 1);
    const auto found = find_patch(frame, set.frames.at(s.from)(s.patch_box), settings);
    hits += !found.empty() && test_support::overlap(found.front().box(), s.truth) >= 0.3 ? 1 : 0;
  }
  return static_cast<double>(hits) / static_cast<double>(set.searches.size());
}

TEST(real_video_localization, default_scales_find_most_people) {
  const auto set = test_support::load_real_video_set(ARGUS_SOURCE_DIR "/tests/data/vtest");
  ASSERT_GE(set.searches.size(), 60u);
  EXPECT_GE(hit_rate(set, {}), 0.75);
}

TEST(real_video_localization, paper_scales_are_too_large_for_these_people) {
  const auto set = test_support::load_real_video_set(ARGUS_SOURCE_DIR "/tests/data/vtest");
  scale_settings paper;
  paper.rule = scale_rule::paper;
  EXPECT_LE(hit_rate(set, paper), 0.1);
}

}  // namespace
}  // namespace argus::vision
