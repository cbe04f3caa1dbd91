// The fast localiser (multiscale_localizer) against a straightforward implementation of
// Fig. 9 kept here: same boxes, scales and scores, bit for bit, on random scenes. The
// reference evaluates the same arithmetic in the plainest way: the integral image of B in
// double (row running sums, then column sums), every B_l(x, y) as four look-ups rounded to
// float, sum_l B_l added in scale order, the first maximum in row-major order (step 2),
// per-scale peaks and sharpness summed pixel by pixel in row-major order (steps 3 and 4),
// and after a removal (step 6) the integral recomputed from scratch and the sum recomputed
// wherever a kernel reaches the removed box.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <random>

#include "opencv2/imgproc.hpp"
#include "vision/backprojection.hpp"
#include "vision/multiscale_localizer.hpp"

namespace argus::vision {
namespace {

struct reference_localizer {
  cv::Mat work;      // B with the accepted boxes zeroed
  cv::Mat integral;  // (h + 1) x (w + 1), double
  cv::Mat sum;
  std::vector<int> scales;

  void integrate() {
    integral = cv::Mat::zeros(work.rows + 1, work.cols + 1, CV_64F);
    for (int y = 0; y < work.rows; ++y) {
      double running = 0.0;
      for (int x = 0; x < work.cols; ++x) {
        running += work.at<float>(y, x);
        integral.at<double>(y + 1, x + 1) = integral.at<double>(y, x + 1) + running;
      }
    }
  }

  // The integral image extended with zeros: rows clamped, columns clamped (left: 0, right:
  // the row's last entry).
  double at(int y, int x) const {
    y = std::clamp(y, 0, integral.rows - 1);
    x = std::clamp(x, 0, integral.cols - 1);
    return integral.at<double>(y, x);
  }

  // B_l(x, y): the box rows y - 3l .. y + 3l, columns x - l .. x + l.
  float response(int l, int x, int y) const {
    return static_cast<float>((at(y + 3 * l + 1, x + l + 1) - at(y + 3 * l + 1, x - l)) -
                              (at(y - 3 * l, x + l + 1) - at(y - 3 * l, x - l)));
  }

  void compute_sum(const cv::Rect& area) {
    for (int y = area.y; y < area.y + area.height; ++y)
      for (int x = area.x; x < area.x + area.width; ++x) {
        float s = 0.0f;
        for (int l : scales) s += response(l, x, y);
        sum.at<float>(y, x) = s;
      }
  }

  std::vector<localized_region> localize(const cv::Mat& b, const localizer_settings& settings,
                                         const region_scorer& score) {
    std::vector<localized_region> found;
    work = b.clone();
    scales = settings.scales.empty() ? paper_scales(b.rows) : settings.scales;
    const int largest = *std::max_element(scales.begin(), scales.end());
    const cv::Rect image(0, 0, b.cols, b.rows);
    integrate();
    sum.create(b.size(), CV_32F);
    compute_sum(image);
    while (static_cast<int>(found.size()) < settings.max_regions) {
      // Step 2: the first maximum in row-major order.
      float best = -std::numeric_limits<float>::infinity();
      cv::Point centre;
      for (int y = 0; y < sum.rows; ++y)
        for (int x = 0; x < sum.cols; ++x)
          if (sum.at<float>(y, x) > best) {
            best = sum.at<float>(y, x);
            centre = {x, y};
          }
      if (best <= 1e-6) break;
      // Steps 3 and 4.
      int best_scale = scales.front();
      double best_sharpness = -1.0;
      for (int l : scales) {
        const auto domain = kernel_domain(centre, l) & image;
        float peak = -std::numeric_limits<float>::infinity();
        for (int y = domain.y; y < domain.br().y; ++y)
          for (int x = domain.x; x < domain.br().x; ++x) peak = std::max(peak, response(l, x, y));
        double squares = 0.0;
        for (int y = domain.y; y < domain.br().y; ++y)
          for (int x = domain.x; x < domain.br().x; ++x) {
            double d = static_cast<double>(peak) - response(l, x, y);
            squares += d * d;
          }
        double sharpness = squares / domain.area();
        if (sharpness > best_sharpness) {
          best_sharpness = sharpness;
          best_scale = l;
        }
      }
      // Step 5.
      const auto box = kernel_domain(centre, best_scale) & image;
      const double box_score = score(box);
      if (!(box_score > settings.rho)) break;
      found.push_back({box.x, box.y, box.width, box.height, box_score, best_scale});
      // Step 6.
      work(box).setTo(0.0f);
      integrate();
      compute_sum(cv::Rect(box.x - largest, box.y - 3 * largest, box.width + 2 * largest,
                           box.height + 6 * largest) &
                  image);
      for (const auto& region : found) sum(region.box()).setTo(-1.0f);
    }
    return found;
  }
};

void expect_same(const std::vector<localized_region>& fast,
                 const std::vector<localized_region>& reference, const std::string& what) {
  ASSERT_EQ(fast.size(), reference.size()) << what;
  for (std::size_t k = 0; k < fast.size(); ++k) {
    EXPECT_EQ(fast[k].box(), reference[k].box()) << what << " region " << k;
    EXPECT_EQ(fast[k].scale, reference[k].scale) << what << " region " << k;
    EXPECT_EQ(fast[k].score, reference[k].score) << what << " region " << k;
  }
}

// A textured frame with a few pedestrians in a handful of colours.
cv::Mat random_scene(cv::Size size, std::mt19937& rng, cv::Rect& first) {
  cv::Mat image(size, CV_8UC3);
  std::uniform_int_distribution<int> shade(40, 200);
  for (int y = 0; y < size.height; y += 8)
    for (int x = 0; x < size.width; x += 8) {
      int g = shade(rng);
      cv::rectangle(image, cv::Rect(x, y, 8, 8), cv::Scalar(g - 20, g, g + 10), cv::FILLED);
    }
  const std::vector<cv::Scalar> colours{{30, 30, 200},  {140, 60, 20},  {40, 170, 40},
                                        {30, 200, 220}, {200, 40, 160}, {20, 120, 240}};
  std::uniform_int_distribution<int> colour(0, static_cast<int>(colours.size()) - 1);
  std::uniform_int_distribution<int> people(1, 5);
  const int n = people(rng);
  for (int k = 0; k < n; ++k) {
    std::uniform_int_distribution<int> height(size.height / 8, size.height * 3 / 4);
    const int h = height(rng);
    std::uniform_int_distribution<int> x(-h / 6, size.width - h / 6);
    std::uniform_int_distribution<int> y(-h / 4, size.height - h / 2);
    const cv::Rect box(x(rng), y(rng), std::max(1, h / 3), h);
    cv::rectangle(image, cv::Rect(box.x, box.y, box.width, h / 2), colours[colour(rng)],
                  cv::FILLED);
    cv::rectangle(image, cv::Rect(box.x, box.y + h / 2, box.width, h - h / 2), colours[colour(rng)],
                  cv::FILLED);
    if (k == 0) first = box & cv::Rect(0, 0, size.width, size.height);
  }
  if (first.empty()) first = cv::Rect(0, 0, size.width / 4, size.height / 2);
  cv::Mat noise(size, CV_8UC3);
  cv::randn(noise, cv::Scalar::all(0),
            cv::Scalar::all(std::uniform_int_distribution<int>(0, 8)(rng)));
  image += noise;
  return image;
}

// Colour scenes through the whole pipeline (backprojection, histogram_scorer).
TEST(multiscale_localizer_equivalence, colour_scenes_match_the_reference) {
  std::mt19937 rng(2024);
  multiscale_localizer fast({{}, 0.5, 8});  // reused across frames, as a camera does
  std::size_t regions = 0;
  for (int scene = 0; scene < 40; ++scene) {
    const cv::Size size = scene % 4 == 3 ? cv::Size(640, 480) : cv::Size(320, 240);
    cv::Rect target_box;
    const cv::Mat frame = random_scene(size, rng, target_box);
    const auto target = color_histogram::of_region(frame, target_box);
    const auto bp = backproject_target(frame, target);
    const auto scorer = histogram_scorer(bp.bin_indices, target);
    const double rho = scene % 3 == 0 ? 0.3 : 0.5;
    localizer_settings settings{{}, rho, 8};
    multiscale_localizer fresh(settings);
    const auto expected = reference_localizer{}.localize(bp.backprojection, settings, scorer);
    regions += expected.size();
    expect_same(fresh.localize(bp.backprojection, scorer), expected,
                "scene " + std::to_string(scene));
    if (rho == 0.5)
      expect_same(fast.localize(bp.backprojection, scorer), expected,
                  "reused, scene " + std::to_string(scene));
  }
  EXPECT_GT(regions, 40u);  // the scenes exercise removal and repetition (step 6)
  std::cout << regions << " regions\n";
}

// Synthetic backprojections with many exact ties (values in steps of 1/4, flat rectangles),
// some with negative values, odd sizes, hand-picked scale sets (l = 0 included) and the
// single-scale baseline.
TEST(multiscale_localizer_equivalence, synthetic_backprojections_match_the_reference) {
  std::mt19937 rng(99);
  std::size_t regions = 0;
  for (int scene = 0; scene < 40; ++scene) {
    std::uniform_int_distribution<int> side(1, 130);
    const cv::Size size(side(rng) + 3, side(rng) + 3);
    cv::Mat b(size, CV_32F);
    if (scene % 2 == 0) {
      cv::randu(b, 0.0f, 1.0f);
      b = b.mul(b).mul(b);  // mostly small, some large
    } else {
      b.setTo(0.0f);
    }
    std::uniform_int_distribution<int> quarter(1, 4);
    for (int k = 0; k < 4; ++k) {
      std::uniform_int_distribution<int> x(-10, size.width), y(-10, size.height), w(1, 40);
      b(cv::Rect(x(rng), y(rng), w(rng), 3 * w(rng)) & cv::Rect({}, size))
          .setTo(quarter(rng) / 4.0f);
    }
    if (scene % 4 == 3) b -= 0.1f;  // negative values too (as in a noisy B, Fig. 9 (b))
    std::vector<int> scales;
    if (scene % 5 == 1) scales = {0, 1, 2};
    if (scene % 5 == 2) scales = {std::uniform_int_distribution<int>(0, 9)(rng)};
    if (scene % 5 == 3) scales = {2, 5, 3, 11};
    const localizer_settings settings{scales, 0.2, 6};
    auto mean_of = [&b](const cv::Rect& box) { return cv::mean(b(box))[0]; };
    multiscale_localizer fast(settings);
    const auto expected = reference_localizer{}.localize(b, settings, mean_of);
    regions += expected.size();
    expect_same(fast.localize(b, mean_of), expected, "synthetic scene " + std::to_string(scene));
    if (scales.size() == 1)
      expect_same(localize_single_scale(b, scales[0], mean_of, 0.2, 6),
                  reference_localizer{}.localize(b, settings, mean_of),
                  "single scale, scene " + std::to_string(scene));
  }
  EXPECT_GT(regions, 40u);
  std::cout << regions << " regions\n";
}

}  // namespace
}  // namespace argus::vision
