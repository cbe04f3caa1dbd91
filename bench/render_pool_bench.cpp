// Frames per second through the actors for the paper's Penn Station scene: 100 pedestrians,
// the 16 cameras of scenarios/penn_station.yaml, 320x240, imaging model on. Each iteration asks
// for all 16 cameras' frames at once and waits for them, as a tick of a pixel run does.
//
// bm_render_pool_penn_station: the render pool (actors/render_pool.hpp), 1 and 2 detached
// render workers (one EGL context each), as the video recorder uses it; argument: workers.
// bm_shared_renderers_penn_station: what a pixel run's camera nodes do
// (actors/shared_renderers.hpp): 16 actors, one per camera, each rendering its own frame inside
// its handler on a scheduler of 1 or 2 threads, as many renderers as threads; argument: threads.

#include <benchmark/benchmark.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "actors/render_pool.hpp"
#include "actors/shared_renderers.hpp"
#include "actors/system_config.hpp"
#include "actors/type_ids.hpp"
#include "config/scenario_loader.hpp"
#include "vision/imaging_model.hpp"
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

// The same degradation as bench/render_bench.cpp.
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

// Asks `renderer_of(k)` for camera k's frame, all 16 at once, per iteration, and waits for
// them; counts frames per second.
void measure(benchmark::State& state, caf::actor_system& system,
             const std::function<caf::actor(std::size_t)>& renderer_of) {
  const auto& s = penn_station();
  std::vector<vision::camera_view> views;
  std::vector<std::optional<vision::imaging_model>> models;
  for (const auto& c : s.scenario.cameras) {
    views.push_back(
        {vision::camera_placement::from(c), vision::ptz_camera::from(c).state(), 320, 240});
    models.push_back(
        vision::imaging_model::for_camera(degraded(320, 240), s.scenario.run.seed, c.id));
  }
  double t = s.frame->time().count();
  std::size_t frames = 0;
  caf::scoped_actor self{system};
  for (auto _ : state) {
    std::vector<caf::response_handle<caf::blocking_actor, caf::message, true>> pending;
    for (std::size_t k = 0; k < views.size(); ++k)
      pending.push_back(self->request(
          renderer_of(k), caf::infinite, actors::render_atom_v,
          actors::render_request{views[k], s.frame, t, 1.0 / 30.0, std::move(models[k])}));
    for (std::size_t k = 0; k < views.size(); ++k)
      pending[k].receive(
          [&](actors::render_result& r) {
            models[k] = std::move(r.imaging);
            benchmark::DoNotOptimize(r.image.data);
          },
          [&](caf::error& err) { state.SkipWithError(system.render(err).c_str()); });
    frames += views.size();
    t += 1.0 / 15.0;
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
}

void bm_render_pool_penn_station(benchmark::State& state) {
  const auto workers = static_cast<std::size_t>(state.range(0));
  actors::system_config cfg(1);
  caf::actor_system system{cfg};
  auto pool = actors::spawn_render_pool(system, penn_station().station, workers);
  measure(state, system, [&](std::size_t) { return pool.front; });
  caf::anon_send_exit(pool.front, caf::exit_reason::user_shutdown);
}

// One camera's stand-in: renders the frames it is asked for, in its own handler.
caf::behavior camera_stand_in(caf::event_based_actor*,
                              std::shared_ptr<actors::shared_renderers> renderers) {
  return {[renderers](actors::render_atom, actors::render_request& request) {
    return renderers->render(std::move(request));
  }};
}

void bm_shared_renderers_penn_station(benchmark::State& state) {
  const auto threads = static_cast<unsigned>(state.range(0));
  actors::system_config cfg(threads);
  caf::actor_system system{cfg};
  auto renderers = std::make_shared<actors::shared_renderers>(penn_station().station, threads);
  std::vector<caf::actor> cameras;
  for (std::size_t k = 0; k < penn_station().scenario.cameras.size(); ++k)
    cameras.push_back(system.spawn(camera_stand_in, renderers));
  measure(state, system, [&](std::size_t k) { return cameras[k]; });
  for (auto& c : cameras) caf::anon_send_exit(c, caf::exit_reason::user_shutdown);
}

BENCHMARK(bm_shared_renderers_penn_station)
    ->ArgNames({"threads"})
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

BENCHMARK(bm_render_pool_penn_station)
    ->ArgNames({"workers"})
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
