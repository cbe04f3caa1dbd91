// Low-level visual routines: per-frame cost of backprojection (bin map, image histogram,
// ratio histogram, B) plus multiscale localisation (Fig. 9, 10 scales) at 320x240 and
// 640x480, one thread. Target: under 1 ms per frame at 320x240 (issue 5).
#include <benchmark/benchmark.h>

#include <random>

#include "opencv2/core.hpp"
#include "opencv2/imgproc.hpp"
#include "vision/backprojection.hpp"
#include "vision/multiscale_localizer.hpp"

namespace {

using namespace argus::vision;

// A textured frame with three pedestrians, one of them the target.
cv::Mat scene(int width, int height, cv::Rect& target_box) {
  cv::Mat image(height, width, CV_8UC3);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> shade(60, 170);
  for (int y = 0; y < height; y += 8)
    for (int x = 0; x < width; x += 8) {
      int g = shade(rng);
      cv::rectangle(image, cv::Rect(x, y, 8, 8), cv::Scalar(g - 20, g, g + 10), cv::FILLED);
    }
  auto person = [&](cv::Point at, int h, cv::Scalar shirt, cv::Scalar trousers) {
    cv::rectangle(image, cv::Rect(at.x, at.y, h / 3, h / 2), shirt, cv::FILLED);
    cv::rectangle(image, cv::Rect(at.x, at.y + h / 2, h / 3, h / 2), trousers, cv::FILLED);
    return cv::Rect(at.x, at.y, h / 3, h);
  };
  target_box = person({width / 8, height / 6}, height / 2, {30, 30, 200}, {140, 60, 20});
  person({width / 2, height / 4}, height / 3, {40, 170, 40}, {30, 200, 220});
  person({3 * width / 4, height / 5}, height / 4, {30, 30, 200}, {140, 60, 20});
  return image;
}

void backproject_and_localize(benchmark::State& state) {
  cv::setNumThreads(1);
  const int width = static_cast<int>(state.range(0));
  const int height = static_cast<int>(state.range(1));
  cv::Rect box;
  const cv::Mat frame = scene(width, height, box);
  const auto target = color_histogram::of_region(frame, box);
  multiscale_localizer localizer({{}, 0.5, 8});
  std::size_t found = 0;
  for (auto _ : state) {
    auto bp = backproject_target(frame, target);
    auto regions = localizer.localize(bp.backprojection, histogram_scorer(bp.bin_indices, target));
    found = regions.size();
    benchmark::DoNotOptimize(regions.data());
  }
  state.counters["regions"] = static_cast<double>(found);
}
BENCHMARK(backproject_and_localize)
    ->Args({320, 240})
    ->Args({640, 480})
    ->Unit(benchmark::kMillisecond);

void backproject_only(benchmark::State& state) {
  cv::setNumThreads(1);
  cv::Rect box;
  const cv::Mat frame =
      scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), box);
  const auto target = color_histogram::of_region(frame, box);
  for (auto _ : state)
    benchmark::DoNotOptimize(backproject_target(frame, target).backprojection.data);
}
BENCHMARK(backproject_only)->Args({320, 240})->Args({640, 480})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
