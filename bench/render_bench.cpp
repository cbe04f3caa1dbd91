// Frames per second of the synthetic video pipeline (Section III-A) for the paper's Penn
// Station scene: 100 pedestrians, the 16 cameras of scenarios/penn_station.yaml, at 320x240
// and 640x480, with and without the imaging model, on 1 and 2 render threads (one renderer
// = one EGL context per thread). Each iteration renders all 16 cameras once.
//
// Arguments: width, imaging model (0/1), render threads.

#include <benchmark/benchmark.h>

#include <future>
#include <memory>
#include <vector>

#include "config/scenario_loader.hpp"
#include "vision/imaging_model.hpp"
#include "vision/renderer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace {

using namespace argus;

struct scene {
  config::scenario scenario;
  std::shared_ptr<const world::station> station;
  std::shared_ptr<const world::snapshot> frame;
};

const scene& penn_station() {
  static const scene s = [] {
    scene out;
    out.scenario = config::load_scenario(ARGUS_SOURCE_DIR "/scenarios/penn_station.yaml");
    out.station = world::station::load(world::layout_path(out.scenario));
    auto settings = world::crowd_settings::from(out.scenario);
    settings.population = 100;
    world::crowd crowd(out.station, settings);
    for (int k = 0; k < 300; ++k) crowd.step();  // 20 s: people spread out and walking
    out.frame = crowd.current();
    return out;
  }();
  return s;
}

// A surveillance-grade degradation with every per-frame effect on (interlacing would render
// twice; it is measured by the renderer figures).
config::imaging_model degraded(int width, int height) {
  config::imaging_model m;
  m.width_px = static_cast<unsigned>(width);
  m.height_px = static_cast<unsigned>(height);
  m.color_response_enabled = true;
  m.response.hue_offset_deg = 4.0;
  m.response.saturation_gain = 0.9;
  m.response.tint = 0.05;
  m.noise_sigma = 4.0;
  m.dropout_fraction = 0.002;
  m.jpeg_quality = 75;
  return m;
}

struct worker {
  std::unique_ptr<vision::renderer> renderer;
  std::vector<vision::camera_view> views;
  std::vector<vision::imaging_model> models;

  void render_all(double time_s, bool imaging) {
    for (std::size_t k = 0; k < views.size(); ++k) {
      cv::Mat image = renderer->render(views[k], *penn_station().frame, time_s);
      if (imaging) image = models[k].apply(image);
      benchmark::DoNotOptimize(image.data);
    }
  }
};

void bm_render_penn_station(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  const int height = width * 3 / 4;
  const bool imaging = state.range(1) != 0;
  const auto threads = static_cast<std::size_t>(state.range(2));
  const auto& s = penn_station();
  std::vector<worker> workers(threads);
  for (auto& w : workers) w.renderer = std::make_unique<vision::renderer>(s.station);
  for (std::size_t k = 0; k < s.scenario.cameras.size(); ++k) {
    const auto& c = s.scenario.cameras[k];
    auto& w = workers[k % threads];
    w.views.push_back(
        {vision::camera_placement::from(c), vision::ptz_camera::from(c).state(), width, height});
    w.models.push_back(
        vision::imaging_model::for_camera(degraded(width, height), s.scenario.run.seed, c.id));
  }
  double t = s.frame->time().count();
  std::size_t frames = 0;
  for (auto _ : state) {
    if (threads == 1) {
      workers[0].render_all(t, imaging);
    } else {
      std::vector<std::future<void>> running;
      for (std::size_t i = 1; i < threads; ++i) {
        running.push_back(
            std::async(std::launch::async, [&, i] { workers[i].render_all(t, imaging); }));
      }
      workers[0].render_all(t, imaging);
      for (auto& r : running) r.get();
    }
    frames += s.scenario.cameras.size();
    t += 1.0 / 15.0;
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
  state.SetLabel(workers[0].renderer->device());
}

BENCHMARK(bm_render_penn_station)
    ->ArgNames({"width", "imaging", "threads"})
    ->ArgsProduct({{320, 640}, {0, 1}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
