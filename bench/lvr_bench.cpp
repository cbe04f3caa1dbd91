// Low-level visual routines: per-frame cost of the pixel pipeline's tracking step, one thread.
//
// - `tracker_update` (issue 17): vision::tracker::update, the step a camera node in Track runs
//   on each frame, with the tracker's own settings (rho 0.4, its search window and scales), on
//   rendered, degraded Penn Station frames (noise sigma 8, JPEG 75, interlaced; 320x240): 16
//   cameras, a sparse (40) and a dense (300) crowd, at the default pose and zoomed so that the
//   target is half the frame high (the tracking zoom). Per camera, the target is the largest
//   unoccluded pedestrian in view; the track is restarted on its ground-truth box before each
//   update, so each update is a Track step from the right place (search window first, whole
//   frame when the window fails). Wall and CPU time per frame; `found` = the fraction of
//   updates that accepted a box.
// - `synthetic_*`: a synthetic checkerboard with three rectangles, rho 0.5, the fast paths of
//   the localiser (tile pruning, dyadic ratios): backprojection plus Fig. 9 multiscale
//   localisation at 320x240 and 640x480 (issue 5's target: under 1 ms at 320x240).
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <vector>

#include "config/scenario_loader.hpp"
#include "opencv2/core.hpp"
#include "opencv2/imgproc.hpp"
#include "vision/backprojection.hpp"
#include "vision/emulated_sensor.hpp"
#include "vision/fixate_zoom.hpp"
#include "vision/imaging_model.hpp"
#include "vision/multiscale_localizer.hpp"
#include "vision/renderer.hpp"
#include "vision/tracker.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace {

using namespace argus;
using namespace argus::vision;

// One camera's degraded frame with the target's ground-truth box and signature in it.
struct tracked_frame {
  cv::Mat image;
  cv::Rect box;
  color_histogram signature;
};

// The largest pedestrian `view` sees whole and unoccluded, at least 12 px tall.
std::optional<pedestrian_view> largest_in_view(const world::snapshot& frame,
                                               const world::station& where,
                                               const camera_view& view) {
  std::optional<pedestrian_view> best;
  const cv::Rect2d image(0.0, 0.0, view.width_px, view.height_px);
  for (const auto& seen : visible_pedestrians(frame, where, view))
    if (seen.occlusion < 0.05 && seen.box.height >= 12.0 && (seen.box & image) == seen.box &&
        (!best || seen.box.area() > best->box.area()))
      best = seen;
  return best;
}

// Penn Station's 16 cameras at `population` after 30 s, each at its default pose or (`zoomed`)
// at the centring pose that makes its target half the frame high.
std::vector<tracked_frame> penn_station_frames(unsigned population, bool zoomed) {
  const int width = 320, height = 240;
  auto scenario = config::load_scenario(ARGUS_SOURCE_DIR "/scenarios/penn_station.yaml");
  std::shared_ptr<const world::station> where = world::station::load(world::layout_path(scenario));
  auto settings = world::crowd_settings::from(scenario);
  settings.population = population;
  settings.spawn_rate_per_min = 3.0 * population;
  world::crowd crowd(where, settings);
  for (int k = 0; k < 450; ++k) crowd.step();
  const auto& now = *crowd.current();
  const double time_s = 30.0;
  config::imaging_model degraded;
  degraded.width_px = width;
  degraded.height_px = height;
  degraded.noise_sigma = 8.0;
  degraded.jpeg_quality = 75;
  degraded.interlace = true;
  static renderer render(where);
  std::vector<tracked_frame> out;
  for (const auto& camera : scenario.cameras) {
    camera_view view{camera_placement::from(camera), ptz_camera::from(camera).state(), width,
                     height};
    auto target = largest_in_view(now, *where, view);
    if (!target) continue;
    if (zoomed) {
      view.pose = ptz_limits::from(camera).clamp(
          centring_pose(view.pose, target->box, {width, height}, 0.5));
      const int id = target->id;
      target.reset();
      for (const auto& seen : visible_pedestrians(now, *where, view))
        if (seen.id == id && seen.occlusion < 0.2) target = seen;
      if (!target) continue;
    }
    auto imaging = imaging_model::for_camera(degraded, scenario.run.seed, camera.id);
    cv::Mat image = imaging.apply(render.render(view, now, time_s),
                                  render.render(view, now, time_s + 1.0 / 30.0));
    const cv::Rect box = cv::Rect(target->box) & cv::Rect(0, 0, width, height);
    // The central part of the box, as tracking_bench takes its signature: the whole box is
    // mostly floor beside a thin body.
    const cv::Rect inner(box.x + box.width / 4, box.y + box.height / 20, std::max(box.width / 2, 1),
                         std::max(box.height * 9 / 10, 1));
    out.push_back({image, box, color_histogram::of_region(image, inner)});
  }
  return out;
}

void tracker_update(benchmark::State& state) {
  cv::setNumThreads(1);
  const bool dense = state.range(0) != 0;
  const bool zoomed = state.range(1) != 0;
  const auto frames = penn_station_frames(dense ? 300 : 40, zoomed);
  if (frames.empty()) {
    state.SkipWithError("no camera sees a usable pedestrian");
    return;
  }
  std::vector<tracker> trackers;
  for (const auto& f : frames) trackers.emplace_back(f.signature);
  std::size_t k = 0, found = 0, updates = 0;
  for (auto _ : state) {
    auto& t = trackers[k];
    t.start(frames[k].box);
    found += t.update(frames[k].image).found;
    ++updates;
    k = (k + 1) % frames.size();
  }
  state.counters["cameras"] = static_cast<double>(frames.size());
  state.counters["found"] = static_cast<double>(found) / static_cast<double>(updates);
  state.SetLabel(std::string(dense ? "dense" : "sparse") +
                 (zoomed ? ", tracking zoom" : ", default zoom"));
}
BENCHMARK(tracker_update)
    ->ArgNames({"dense", "zoomed"})
    ->Args({0, 0})
    ->Args({0, 1})
    ->Args({1, 0})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond);

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

void synthetic_backproject_and_localize(benchmark::State& state) {
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
BENCHMARK(synthetic_backproject_and_localize)
    ->Args({320, 240})
    ->Args({640, 480})
    ->Unit(benchmark::kMillisecond);

void synthetic_backproject_only(benchmark::State& state) {
  cv::setNumThreads(1);
  cv::Rect box;
  const cv::Mat frame =
      scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), box);
  const auto target = color_histogram::of_region(frame, box);
  for (auto _ : state)
    benchmark::DoNotOptimize(backproject_target(frame, target).backprojection.data);
}
BENCHMARK(synthetic_backproject_only)
    ->Args({320, 240})
    ->Args({640, 480})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
