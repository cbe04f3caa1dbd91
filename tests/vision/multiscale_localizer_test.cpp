#include "vision/multiscale_localizer.hpp"

#include <gtest/gtest.h>

#include <random>

#include "opencv2/imgproc.hpp"
#include "vision/backprojection.hpp"

namespace argus::vision {
namespace {

double overlap(const cv::Rect& a, const cv::Rect& b) {  // intersection over union
  double shared = (a & b).area();
  return shared / (a.area() + b.area() - shared);
}

double best_overlap(const std::vector<localized_region>& found, const cv::Rect& truth) {
  double best = 0.0;
  for (const auto& r : found) best = std::max(best, overlap(r.box(), truth));
  return best;
}

region_scorer mean_of(const cv::Mat& b) {
  return [&b](const cv::Rect& box) { return cv::mean(b(box))[0]; };
}

std::vector<float> row_of(const cv::Mat& m) {
  return {m.ptr<float>(0), m.ptr<float>(0) + m.cols};
}

// Fig. 8: I = [0 0 1 1 1 0 0] with zero borders. A one-row image makes the (6l + 1)-high
// kernel a (2l + 1)-tap 1-D kernel: l = 0, 1, 2 are the 1-, 3- and 5-tap kernels.
TEST(multiscale_localizer, fig8_filter_responses) {
  cv::Mat image = (cv::Mat_<float>(1, 7) << 0, 0, 1, 1, 1, 0, 0);
  multiscale_localizer localizer({{0, 1, 2}, 0.5, 1});
  auto found = localizer.localize(image, [](const cv::Rect&) { return 1.0; });
  const auto& b = localizer.responses();
  // The responses before removal equal the reference convolution, and Fig. 8's numbers.
  EXPECT_EQ(row_of(box_response_reference(image, 0)), (std::vector<float>{0, 0, 1, 1, 1, 0, 0}));
  EXPECT_EQ(row_of(box_response_reference(image, 1)), (std::vector<float>{0, 1, 2, 3, 2, 1, 0}));
  EXPECT_EQ(row_of(box_response_reference(image, 2)), (std::vector<float>{1, 2, 3, 3, 3, 2, 1}));
  ASSERT_EQ(b.size(), 3u);
  // The 3-tap kernel (l = 1) matches the target and gives the sharpest peak (Fig. 9, step 4);
  // the sum 1 3 6 7 6 3 1 peaks at x = 3 (step 2).
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].scale, 1);
  EXPECT_EQ(found[0].box(), cv::Rect(2, 0, 3, 1));
}

TEST(multiscale_localizer, fig8_integral_responses_match_the_reference) {
  cv::Mat image = (cv::Mat_<float>(1, 7) << 0, 0, 1, 1, 1, 0, 0);
  for (int l : {0, 1, 2}) {
    multiscale_localizer localizer({{l}, 2.0, 1});  // rho = 2: nothing is removed
    localizer.localize(image, [](const cv::Rect&) { return 1.0; });
    EXPECT_EQ(row_of(localizer.responses()[0]), row_of(box_response_reference(image, l)));
  }
}

TEST(multiscale_localizer, box_sums_match_the_reference_in_2d) {
  cv::Mat image(37, 29, CV_32F);
  cv::randu(image, 0.0f, 1.0f);
  multiscale_localizer localizer({{1, 2, 5}, 1e9, 1});
  localizer.localize(image, [](const cv::Rect&) { return 0.0; });
  for (std::size_t k = 0; k < 3; ++k) {
    cv::Mat expected = box_response_reference(image, localizer.settings().scales[k]);
    EXPECT_LT(cv::norm(localizer.responses()[k], expected, cv::NORM_INF), 1e-3);
  }
}

TEST(multiscale_localizer, paper_scales) {
  // h = 240: l = (0.1 .. 1) x 240 / 7 = 3.4, 6.9, ..., 34.3.
  EXPECT_EQ(paper_scales(240), (std::vector<int>{3, 7, 10, 14, 17, 21, 24, 27, 31, 34}));
  EXPECT_EQ(paper_scales(10), (std::vector<int>{1}));
  // A larger divisor gives smaller kernels: l = (0.1..1) x 240 / 28.
  EXPECT_EQ(paper_scales(240, 28.0), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_THROW(paper_scales(240, 0.0), std::invalid_argument);
  EXPECT_EQ(kernel_domain({10, 20}, 2), cv::Rect(8, 14, 5, 13));  // (6l + 1) x (2l + 1)
}

// Fig. 9 (a), (b): an ideal backprojection with four targets of different sizes, plus noise.
struct fig9_scene {
  cv::Mat clean;
  cv::Mat noisy;
  std::vector<cv::Rect> targets;
};

fig9_scene make_fig9_scene() {
  fig9_scene scene;
  scene.clean = cv::Mat::zeros(240, 320, CV_32F);
  const std::vector<std::pair<cv::Point, int>> centres_and_sizes{
      {{30, 60}, 3}, {{80, 150}, 10}, {{160, 100}, 17}, {{250, 130}, 27}};
  for (auto [centre, l] : centres_and_sizes) {
    scene.targets.push_back(kernel_domain(centre, l));
    scene.clean(scene.targets.back()).setTo(1.0f);
  }
  cv::Mat noise(scene.clean.size(), CV_32F);
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, 0.3);
  // Zero-mean noise: a positive noise floor would make the large kernels' responses fall off
  // towards the zero borders and win step 4 there (a known limitation of step 4).
  scene.noisy = scene.clean + noise;
  return scene;
}

// Fig. 9 (c): the multiscale procedure finds all four regions.
TEST(multiscale_localizer, fig9_multiscale_finds_all_four_targets) {
  auto scene = make_fig9_scene();
  multiscale_localizer localizer;  // paper scales for h = 240, rho = 0.5
  auto found = localizer.localize(scene.noisy, mean_of(scene.noisy));
  EXPECT_EQ(found.size(), 4u);
  for (const auto& truth : scene.targets) EXPECT_GT(best_overlap(found, truth), 0.7) << truth;
}

// Fig. 9 (d)-(f): Swain and Ballard's single-scale localisation with kernel sizes 3, 5 and 7
// localises some targets badly: at least one target has no box overlapping it by half.
TEST(multiscale_localizer, fig9_single_scale_kernels_fail) {
  auto scene = make_fig9_scene();
  for (int l : {3, 5, 7}) {
    auto found = localize_single_scale(scene.noisy, l, mean_of(scene.noisy), 0.5, 16);
    int missed = 0;
    for (const auto& truth : scene.targets) missed += best_overlap(found, truth) < 0.5 ? 1 : 0;
    EXPECT_GE(missed, 2) << "kernel size " << l;
  }
}

TEST(multiscale_localizer, stops_at_first_rejection_and_max_count) {
  auto scene = make_fig9_scene();
  multiscale_localizer strict({{}, 1.5, 16});
  EXPECT_TRUE(strict.localize(scene.noisy, mean_of(scene.noisy)).empty());
  multiscale_localizer two({{}, 0.5, 2});
  EXPECT_EQ(two.localize(scene.noisy, mean_of(scene.noisy)).size(), 2u);
  multiscale_localizer any;
  cv::Mat empty = cv::Mat::zeros(240, 320, CV_32F);
  EXPECT_TRUE(any.localize(empty, [](const cv::Rect&) { return 1.0; }).empty());
}

// A pedestrian drawn with OpenCV: head, shirt and trousers, filling a box of height h and
// width h / 3 (the kernel's aspect) whose top-left corner is `corner`.
cv::Rect draw_pedestrian(cv::Mat& image, cv::Point corner, int h, cv::Scalar shirt,
                         cv::Scalar trousers) {
  const int w = h / 3;
  const int head = h / 7;
  cv::ellipse(image, corner + cv::Point(w / 2, head / 2), cv::Size(std::max(1, w / 4), head / 2), 0,
              0, 360, cv::Scalar(120, 150, 210), cv::FILLED);
  cv::rectangle(image, cv::Rect(corner.x, corner.y + head, w, (h - head) / 2), shirt, cv::FILLED);
  cv::rectangle(image,
                cv::Rect(corner.x + w / 8, corner.y + head + (h - head) / 2, w - w / 4,
                         h - head - (h - head) / 2),
                trousers, cv::FILLED);
  return {corner.x, corner.y, w, h};
}

// A textured floor and wall: random grey-brown blocks with pixel noise.
cv::Mat textured_background(cv::Size size, unsigned seed) {
  cv::Mat image(size, CV_8UC3);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> shade(60, 170);
  for (int y = 0; y < size.height; y += 8)
    for (int x = 0; x < size.width; x += 8) {
      int g = shade(rng);
      cv::rectangle(image, cv::Rect(x, y, 8, 8), cv::Scalar(g - 20, g, g + 10), cv::FILLED);
    }
  cv::Mat noise(size, CV_8UC3);
  cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(6));
  image += noise;
  return image;
}

const cv::Scalar red_shirt(30, 30, 200), blue_trousers(140, 60, 20);
const cv::Scalar green_shirt(40, 170, 40), yellow_trousers(30, 200, 220);

// Localisation of coloured figures across zoom: the target's signature comes from one view,
// and the same pedestrian is found at other sizes, beside a differently dressed one.
TEST(multiscale_localizer, finds_coloured_figures_across_zoom) {
  cv::Mat model = textured_background({320, 240}, 1);
  auto model_box = draw_pedestrian(model, {100, 60}, 90, red_shirt, blue_trousers);
  auto target = color_histogram::of_region(model, model_box);
  for (int height : {43, 85, 127, 187}) {  // 6l + 1 for l = 7, 14, 21, 31
    cv::Mat frame = textured_background({320, 240}, 2 + height);
    auto truth = draw_pedestrian(frame, {40, 30}, height, red_shirt, blue_trousers);
    auto other = draw_pedestrian(frame, {220, 40}, height, green_shirt, yellow_trousers);
    auto bp = backproject_target(frame, target);
    multiscale_localizer localizer({{}, 0.5, 8});
    auto found = localizer.localize(bp.backprojection, histogram_scorer(bp.bin_indices, target));
    ASSERT_FALSE(found.empty()) << "height " << height;
    EXPECT_GT(overlap(found[0].box(), truth), 0.5) << "height " << height;
    EXPECT_EQ(found.size(), 1u) << "height " << height;
    EXPECT_LT(best_overlap(found, other), 0.1) << "height " << height;
  }
}

// Every occurrence: two pedestrians dressed alike, one near and one far.
// Every kernel size fits inside one uniform target, so every size scores the same: the largest
// wins, unless a size is expected (a tracker's last box), then the nearest to it.
TEST(multiscale_localizer, an_expected_size_wins_among_sizes_that_score_alike) {
  cv::Mat b(240, 320, CV_32F, cv::Scalar(0.0f));
  b(cv::Rect(130, 60, 60, 120)).setTo(1.0f);
  localizer_settings settings{{3, 5, 8, 12}, 0.5, 1, scale_choice::score};
  auto chosen = [&] {
    multiscale_localizer localizer(settings);
    const auto found = localizer.localize(b, mean_of(b));
    return found.empty() ? -1 : found.front().scale;
  };
  EXPECT_EQ(chosen(), 12);
  settings.expected_scale = 5.0;
  EXPECT_EQ(chosen(), 5);
  settings.expected_scale = 6.0;  // nearer 5 than 8 in ratio
  EXPECT_EQ(chosen(), 5);
  settings.expected_scale = 30.0;
  EXPECT_EQ(chosen(), 12);
}

TEST(multiscale_localizer, finds_every_occurrence) {
  cv::Mat frame = textured_background({320, 240}, 9);
  auto near = draw_pedestrian(frame, {30, 20}, 150, red_shirt, blue_trousers);
  auto far = draw_pedestrian(frame, {230, 100}, 45, red_shirt, blue_trousers);
  draw_pedestrian(frame, {150, 60}, 90, green_shirt, yellow_trousers);
  auto target = color_histogram::of_region(frame, near);
  auto bp = backproject_target(frame, target);
  multiscale_localizer localizer({{}, 0.5, 8});
  auto found = localizer.localize(bp.backprojection, histogram_scorer(bp.bin_indices, target));
  // Both are found; a sliver of the near one left outside its box may come back as well.
  ASSERT_GE(found.size(), 2u);
  EXPECT_LE(found.size(), 3u);
  EXPECT_GT(best_overlap(found, near), 0.5);
  EXPECT_GT(best_overlap(found, far), 0.5);
}

}  // namespace
}  // namespace argus::vision
