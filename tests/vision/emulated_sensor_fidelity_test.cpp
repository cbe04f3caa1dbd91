// The shipped emulated sensor model (scenarios/sensor_model.yaml, fitted by `argus vision
// calibrate` on penn_station, seeds 1-4, t = 30..270 s, all 16 cameras zoomed to a 20 degree
// field of view at 320 x 240 on undegraded frames, kernels paper_scales(h, 28)) against the
// pixel pipeline on held-out runs: three other seeds and another time window
// (t = 100..160 s), same cameras, zoom and kernels. Tolerances: miss rate within 0.07,
// confusion rate within 0.08. The model sees occlusion and height only; what it does not see
// (how crowded, how alike the people in view are) moves the pixel pipeline's miss rate from
// one seed to the next (0.50 to 0.58 over full windows of seeds 1-4 and 1001 with issue 18's
// crowd), so both the fit and this check pool several seeds.
#include <gtest/gtest.h>

#include "config/scenario_loader.hpp"
#include "vision/capture.hpp"
#include "vision/imaging_model.hpp"
#include "vision/renderer.hpp"
#include "vision/sensor_calibration.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::vision {
namespace {

// The calibration's conditions (see the header of scenarios/sensor_model.yaml): the zoom at
// which cameras track, where pedestrians are 20-160 px high, and the smaller kernels.
constexpr double field_of_view_deg = 20.0;
const scale_settings kernels{scale_rule::paper, 28.0};
constexpr std::size_t cameras = 16;

// One held-out run's trials, the pixel pipeline's and the emulated sensor's, on the same frames.
void add_trials(const config::scenario& scenario, const sensor_model& model,
                std::vector<calibration_trial>& pixels, std::vector<calibration_trial>& emulated) {
  const auto station = world::station::load(world::layout_path(scenario));
  world::crowd crowd(station, world::crowd_settings::from(scenario));
  renderer render(station);
  const double tick_s = scenario.run.tick.count();
  const auto ticks_of = [&](double s) { return static_cast<int>(std::lround(s / tick_s)); };
  std::vector<camera_view> views;
  std::vector<imaging_model> imaging;
  std::vector<emulated_sensor> sensors;
  for (std::size_t c = 0; c < cameras && c < scenario.cameras.size(); ++c) {
    const auto& camera = scenario.cameras[c];
    // The model (scenarios/sensor_model.yaml) was calibrated on undegraded frames; the
    // shipped scenario's cameras degrade theirs (colour response, noise, JPEG, interlacing).
    config::imaging_model settings;
    settings.width_px = 320;
    settings.height_px = 240;
    auto pose = ptz_camera::from(camera).state();
    pose.field_of_view_deg = field_of_view_deg;
    views.push_back({camera_placement::from(camera), pose, 320, 240});
    imaging.push_back(imaging_model::for_camera(settings, scenario.run.seed, camera.id));
    sensors.push_back(emulated_sensor::for_camera(model, scenario.run.seed, camera.id));
  }
  // Held-out window t = 100..160 s, a frame every second.
  const int first = ticks_of(100.0), last = ticks_of(160.0), stride = ticks_of(1.0);
  for (int tick = 1; tick <= last; ++tick) {
    crowd.step();
    if (tick < first || (tick - first) % stride != 0) continue;
    const auto& frame = *crowd.current();
    for (std::size_t c = 0; c < views.size(); ++c) {
      cv::Mat image = capture(render, views[c], frame, tick * tick_s, tick_s / 2.0, imaging[c]);
      auto p = pixel_trials(image, frame, *station, views[c], 0.4, kernels);
      pixels.insert(pixels.end(), p.begin(), p.end());
      auto e = emulated_trials(sensors[c], frame, *station, views[c]);
      emulated.insert(emulated.end(), e.begin(), e.end());
    }
  }
}

TEST(emulated_sensor_fidelity, rates_match_the_pixel_pipeline_on_a_held_out_run) {
  const auto model = load_sensor_model(ARGUS_SOURCE_DIR "/scenarios/sensor_model.yaml");
  ASSERT_GT(model.samples, 1000);
  std::vector<calibration_trial> pixels, emulated;
  for (std::uint64_t held_out = 1001; held_out <= 1003; ++held_out) {  // not the fit's seeds
    auto scenario = config::load_scenario(ARGUS_SOURCE_DIR "/scenarios/penn_station.yaml");
    scenario.run.seed = held_out;
    add_trials(scenario, model, pixels, emulated);
  }
  const auto truth = rates_of(pixels);
  const auto emulation = rates_of(emulated);
  ASSERT_GT(truth.trials, 500);
  EXPECT_EQ(truth.trials, emulation.trials);
  EXPECT_NEAR(emulation.miss, truth.miss, 0.07);
  // What the pixel pipeline measures here: it misses a little over half the visible
  // pedestrians (0.55 over these three windows), far fewer than the 0.97 it missed at the default
  // wide poses with the paper's kernels, and it finds some: the bounds hold 0.55 with room for the
  // window-to-window spread above, and fail for a pipeline that finds nearly everyone or
  // nearly no one.
  EXPECT_GT(truth.miss, 0.45);
  EXPECT_LT(truth.miss, 0.70);
  EXPECT_NEAR(emulation.confusion, truth.confusion, 0.08);
  std::printf(
      "held out: %d trials; miss pixel %.3f emulated %.3f; confusion pixel %.3f emulated "
      "%.3f\n",
      truth.trials, truth.miss, emulation.miss, truth.confusion, emulation.confusion);
}

}  // namespace
}  // namespace argus::vision
