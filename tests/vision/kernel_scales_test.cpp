// The kernel sizes of the multiscale localiser (vision/kernel_scales.hpp): by default they
// follow the target's size, so that a person is found at 20, 60 or 200 px in a 320 x 240 or a
// 768 x 576 frame, after walking toward or away from the camera; the paper's frame-height
// sizes stay available.
#include "vision/kernel_scales.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

#include "opencv2/imgproc.hpp"
#include "vision/patch_search.hpp"

namespace argus::vision {
namespace {

double overlap(const cv::Rect& a, const cv::Rect& b) {
  const double shared = (a & b).area();
  return shared > 0.0 ? shared / (a.area() + b.area() - shared) : 0.0;
}

// A cluttered floor: 8 px tiles of random, mostly dull colours.
cv::Mat floor_of(cv::Size size, unsigned seed) {
  cv::Mat image(size, CV_8UC3);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> shade(40, 200);
  std::uniform_int_distribution<int> tint(-25, 25);
  for (int y = 0; y < size.height; y += 8)
    for (int x = 0; x < size.width; x += 8) {
      const int g = shade(rng);
      cv::rectangle(image, cv::Rect(x, y, 8, 8),
                    cv::Scalar(g + tint(rng), g + tint(rng), g + tint(rng)), cv::FILLED);
    }
  return image;
}

// A standing person `height_px` tall, a third as wide: red shirt over blue trousers.
cv::Rect draw_person(cv::Mat& image, cv::Point centre, int height_px) {
  const int width = std::max(3, height_px / 3);
  const cv::Rect box(centre.x - width / 2, centre.y - height_px / 2, width, height_px);
  cv::rectangle(image, cv::Rect(box.x, box.y, width, height_px / 2), cv::Scalar(30, 30, 200),
                cv::FILLED);
  cv::rectangle(image, cv::Rect(box.x, box.y + height_px / 2, width, height_px - height_px / 2),
                cv::Scalar(150, 70, 20), cv::FILLED);
  return box;
}

struct search_case {
  cv::Size frame;
  int height_px;
};

class person_at_size : public ::testing::TestWithParam<search_case> {};

// The patch is cut where the person was; she is searched for elsewhere in a later frame, a
// fifth taller (walking toward the camera) or, where that would not fit, a fifth shorter.
TEST_P(person_at_size, is_found_with_the_default_scales) {
  const auto [frame, height] = GetParam();
  cv::Mat before = floor_of(frame, 1);
  const cv::Rect patch_box = draw_person(before, {frame.width / 4, frame.height / 2}, height);
  const int later_height = height * 6 / 5 <= frame.height - 8 ? height * 6 / 5 : height * 4 / 5;
  cv::Mat after = floor_of(frame, 2);
  const cv::Rect truth = draw_person(after, {frame.width * 2 / 3, frame.height / 2}, later_height);

  const auto settings =
      localizer_settings_for({}, cv::Size2d(patch_box.size()), frame.height, 0.5, 1);
  // The sizes bracket both the patch's and the later person's kernel.
  EXPECT_LE(settings.scales.front(), kernel_size_for(cv::Size2d(truth.size())));
  EXPECT_GE(settings.scales.back(),
            std::min<double>(kernel_size_for(cv::Size2d(truth.size())), (frame.height - 1) / 6));
  const auto found = find_patch(after, before(patch_box), settings);
  ASSERT_FALSE(found.empty());
  EXPECT_GE(overlap(found.front().box(), truth), 0.5)
      << "found " << found.front().box() << ", true " << truth;
}

INSTANTIATE_TEST_SUITE_P(kernel_scales, person_at_size,
                         ::testing::Values(search_case{{320, 240}, 20}, search_case{{320, 240}, 60},
                                           search_case{{320, 240}, 200},
                                           search_case{{768, 576}, 20}, search_case{{768, 576}, 60},
                                           search_case{{768, 576}, 200}),
                         [](const auto& info) {
                           return std::to_string(info.param.frame.width) + "x" +
                                  std::to_string(info.param.frame.height) + "_" +
                                  std::to_string(info.param.height_px) + "px";
                         });

// Why the default changed: the paper's smallest kernel in a 576-row frame is 49 rows, so a
// person 20 px tall gets a box more than twice her size at best.
TEST(kernel_scales, paper_scales_miss_a_small_person_in_a_large_frame) {
  const cv::Size frame(768, 576);
  cv::Mat before = floor_of(frame, 1);
  const cv::Rect patch_box = draw_person(before, {200, 300}, 20);
  cv::Mat after = floor_of(frame, 2);
  const cv::Rect truth = draw_person(after, {500, 300}, 20);
  scale_settings paper;
  paper.rule = scale_rule::paper;
  const auto settings = localizer_settings_for(paper, cv::Size2d(patch_box.size()), 576, 0.5, 1);
  EXPECT_EQ(settings.scales, paper_scales(576));
  EXPECT_EQ(settings.choice, scale_choice::sharpness);
  const auto found = find_patch(after, before(patch_box), settings);
  EXPECT_TRUE(found.empty() || overlap(found.front().box(), truth) < 0.3);
}

TEST(kernel_scales, target_scales_span_half_to_twice_the_size_in_quarter_octaves) {
  // A 30 x 90 patch: the kernel of its area has l = 14.67 (6l + 1 = 89 rows, 2l + 1 = 30.3
  // columns); the sizes for 0.5, 0.59, ..., 2 times it.
  EXPECT_NEAR(kernel_size_for({30.0, 90.0}), 14.67, 0.01);
  EXPECT_EQ(target_scales({30.0, 90.0}, 576), (std::vector<int>{7, 9, 10, 12, 15, 18, 21, 25, 30}));
  // Clamped to 1 and to the largest kernel that fits the frame (6l + 1 <= 240: l <= 39).
  EXPECT_EQ(target_scales({2.0, 3.0}, 240).front(), 1);
  EXPECT_EQ(target_scales({100.0, 300.0}, 240).back(), 39);
  // One size when span is 1.
  scale_settings exact;
  exact.span = 1.0;
  EXPECT_EQ(target_scales({30.0, 90.0}, 576, exact), (std::vector<int>{15}));
  scale_settings bad;
  bad.span = 0.5;
  EXPECT_THROW(target_scales({30.0, 90.0}, 576, bad), std::invalid_argument);
}

// A user's list in any order: the same box as sorted.
TEST(kernel_scales, explicit_sizes_in_any_order_give_the_same_box) {
  const cv::Size frame(320, 240);
  cv::Mat before = floor_of(frame, 1);
  const cv::Rect patch_box = draw_person(before, {80, 120}, 60);
  cv::Mat after = floor_of(frame, 2);
  draw_person(after, {200, 120}, 66);
  auto settings = localizer_settings_for({}, cv::Size2d(patch_box.size()), 240, 0.5, 1);
  const auto sorted = find_patch(after, before(patch_box), settings);
  std::reverse(settings.scales.begin(), settings.scales.end());
  const auto reversed = find_patch(after, before(patch_box), settings);
  ASSERT_EQ(sorted.size(), 1u);
  ASSERT_EQ(reversed.size(), 1u);
  EXPECT_EQ(sorted.front().box(), reversed.front().box());
}

TEST(kernel_scales, unknown_size_falls_back_to_the_paper_scales) {
  EXPECT_EQ(kernel_scales({}, std::nullopt, 240), paper_scales(240));
  EXPECT_EQ(kernel_scales({}, cv::Size2d(0.0, 0.0), 240), paper_scales(240));
  scale_settings d28;
  d28.rule = scale_rule::paper;
  d28.paper_divisor = 28.0;
  EXPECT_EQ(kernel_scales(d28, cv::Size2d(30.0, 90.0), 240), paper_scales(240, 28.0));
}

}  // namespace
}  // namespace argus::vision
