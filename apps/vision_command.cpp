// `argus vision localize`: every occurrence of a target patch's colour distribution in an
// image, by histogram backprojection and the multiscale localiser (paper Fig. 9).
// `argus vision calibrate`: fits the emulated sensor's error model to the pixel pipeline run
// side by side with the ground truth on a scenario.

#include <fstream>
#include <iostream>
#include <optional>

#include "CLI/CLI.hpp"
#include "apps/color_image.hpp"
#include "apps/kernel_scales_option.hpp"
#include "apps/option_checks.hpp"
#include "apps/time_option.hpp"
#include "config/duration.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "config/ticks.hpp"
#include "fmt/format.h"
#include "nlohmann/json.hpp"
#include "vision/capture.hpp"
#include "vision/imaging_model.hpp"
#include "vision/multiscale_localizer.hpp"
#include "vision/patch_search.hpp"
#include "vision/renderer.hpp"
#include "vision/sensor_calibration.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::apps {
namespace {

constexpr int ok = 0;
constexpr int run_failed = 1;
constexpr int bad_input = 2;

struct localize_arguments {
  std::string image;
  std::string target;
  double rho = 0.5;
  std::optional<int> single_scale;
  std::string scales = "target";
  int max_regions = 16;
};

// The localiser's settings for `args` (--single-scale, --scales) on a `frame_height` high
// image and a `patch`-sized target; explicit sizes are chosen among as under 'target'.
vision::localizer_settings localize_settings(const localize_arguments& args, const cv::Size& patch,
                                             int frame_height) {
  vision::scale_settings scales;
  if (args.scales == "paper") scales.rule = vision::scale_rule::paper;
  auto settings = vision::localizer_settings_for(scales, cv::Size2d(patch), frame_height, args.rho,
                                                 args.max_regions);
  if (args.single_scale)
    settings.scales = {*args.single_scale};
  else if (args.scales != "target" && args.scales != "paper")
    settings.scales = *kernel_size_list(args.scales);
  return settings;
}

int localize(const localize_arguments& args) {
  const auto image = read_color_image("argus vision localize", "--image", args.image);
  if (!image) return bad_input;
  const auto patch = read_color_image("argus vision localize", "--target", args.target);
  if (!patch) return bad_input;
  const auto found =
      vision::find_patch(*image, *patch, localize_settings(args, patch->size(), image->rows));
  auto regions = nlohmann::json::array();
  for (const auto& r : found)
    regions.push_back(
        {{"x", r.x}, {"y", r.y}, {"width", r.width}, {"height", r.height}, {"score", r.score}});
  std::cout << regions.dump(2) << '\n';
  return ok;
}

struct calibrate_arguments {
  std::string scenario;
  std::string start = "30 s";
  std::string duration = "60 s";
  std::string every = "1 s";
  int cameras = 4;
  int width = 320;
  int height = 240;
  std::optional<std::uint64_t> seed;
  // Zoomed poses: cameras track at a narrow field of view (the fixate and zoom controller
  // makes the target half the frame high), where pedestrians are tall enough for the
  // localiser's kernels; the default poses see most of them only a few pixels high.
  std::optional<double> field_of_view_deg;
  // Localiser kernels: around each pedestrian's size, or l = (0.1..1) x h / scale_divisor
  // (7 is the paper's); --scale-divisor alone means the paper's, as before --scales existed.
  std::optional<std::string> scales;
  std::optional<double> scale_divisor;
  // Seeds pooled: the first (--seed, or the scenario's) and the next seeds - 1.
  int seeds = 1;
  // Fit on undegraded frames (each camera's imaging model left out but for its size).
  bool raw = false;
  std::string out;
};

int calibrate(const calibrate_arguments& args) {
  const std::string scales = args.scales.value_or(args.scale_divisor ? "paper" : "target");
  if (args.scale_divisor && scales != "paper") {
    std::cerr << "argus vision calibrate: --scale-divisor: applies to --scales paper only\n";
    return bad_input;
  }
  vision::scale_settings kernels;
  if (scales == "paper") kernels.rule = vision::scale_rule::paper;
  kernels.paper_divisor = args.scale_divisor.value_or(kernels.paper_divisor);
  const auto start_s = seconds_of(args.start);
  const auto duration_s = seconds_of(args.duration);
  const auto every_s = seconds_of(args.every);
  if (!start_s || !duration_s || !every_s || *every_s <= 0.0) {
    std::cerr << "argus vision calibrate: --start, --duration, --every: expected durations such "
                 "as '60 s' (--every > 0)\n";
    return bad_input;
  }
  config::scenario scenario;
  std::shared_ptr<const world::station> station;
  try {
    scenario = config::load_scenario(args.scenario);
    station = world::station::load(world::layout_path(scenario));
  } catch (const config::scenario_error& e) {
    std::cerr << e.what() << '\n';
    return bad_input;
  } catch (const std::exception& e) {
    std::cerr << "argus vision calibrate: " << args.scenario << ": " << e.what() << '\n';
    return bad_input;
  }
  if (args.seed) scenario.run.seed = *args.seed;
  try {
    const double tick_s = scenario.run.tick.count();
    const auto ticks_of = [&](double s) {
      return config::to_ticks(config::seconds{s}, scenario.run.tick);
    };
    const std::int64_t first = ticks_of(*start_s);
    const std::int64_t last = first + ticks_of(*duration_s);
    const std::int64_t stride = std::max<std::int64_t>(1, ticks_of(*every_s));
    // Several seeds pool their trials: one crowd's density and look-alikes move the pixel
    // pipeline's miss rate by several points from one seed to the next.
    std::vector<vision::calibration_trial> trials;
    const std::uint64_t first_seed = scenario.run.seed;
    for (int k = 0; k < args.seeds; ++k) {
      scenario.run.seed = first_seed + static_cast<std::uint64_t>(k);
      world::crowd crowd(station, world::crowd_settings::from(scenario));
      vision::renderer renderer(station);
      struct camera_run {
        vision::camera_view view;
        vision::imaging_model imaging;
      };
      std::vector<camera_run> cameras;
      for (const auto& c : scenario.cameras) {
        if (static_cast<int>(cameras.size()) >= args.cameras) break;
        config::imaging_model imaging = args.raw ? config::imaging_model{} : c.imaging;
        imaging.width_px = static_cast<unsigned>(args.width);
        imaging.height_px = static_cast<unsigned>(args.height);
        auto pose = vision::ptz_camera::from(c).state();
        if (args.field_of_view_deg) pose.field_of_view_deg = *args.field_of_view_deg;
        cameras.push_back({{vision::camera_placement::from(c), pose, args.width, args.height},
                           vision::imaging_model::for_camera(imaging, scenario.run.seed, c.id)});
      }
      for (std::int64_t tick = 0; tick <= last; ++tick) {
        if (tick > 0) crowd.step();
        if (tick < first || (tick - first) % stride != 0) continue;
        const double t = static_cast<double>(tick) * tick_s;
        const auto& frame = *crowd.current();
        for (auto& camera : cameras) {
          cv::Mat image =
              vision::capture(renderer, camera.view, frame, t, tick_s / 2.0, camera.imaging);
          auto more = vision::pixel_trials(image, frame, *station, camera.view, 0.4, kernels);
          trials.insert(trials.end(), more.begin(), more.end());
        }
      }
    }
    scenario.run.seed = first_seed;
    const auto model = vision::fit_sensor_model(trials);
    const auto rates = vision::rates_of(trials);
    std::cerr << vision::describe(trials);
    std::cerr << fmt::format("{} trials: miss rate {:.3f}, confusion rate {:.3f}\n", rates.trials,
                             rates.miss, rates.confusion);
    std::ofstream out(args.out);
    if (!out) {
      std::cerr << fmt::format("argus vision calibrate: cannot write {}\n", args.out);
      return run_failed;
    }
    out << fmt::format(
        "# Emulated sensor error model (vision/sensor_model.hpp), fitted by:\n"
        "#   argus vision calibrate {} --start '{}' --duration '{}' --every '{}' --cameras {} "
        "--width {} --height {}{}{}{} --scales {}{}{} --out {}\n"
        "# {} trials: miss rate {:.3f}, confusion rate {:.3f} (pixel pipeline)\n",
        args.scenario, args.start, args.duration, args.every, args.cameras, args.width, args.height,
        args.seed ? fmt::format(" --seed {}", *args.seed) : "",
        args.seeds > 1 ? fmt::format(" --seeds {}", args.seeds) : "",
        args.field_of_view_deg ? fmt::format(" --field-of-view {}", *args.field_of_view_deg) : "",
        scales, args.scale_divisor ? fmt::format(" --scale-divisor {}", *args.scale_divisor) : "",
        args.raw ? " --raw" : "", args.out, rates.trials, rates.miss, rates.confusion);
    out << vision::to_yaml(model);
    std::cout << fmt::format("{}: {} cameras, {} seeds, {} trials; model written to {}\n",
                             scenario.name,
                             std::min<std::size_t>(args.cameras, scenario.cameras.size()),
                             args.seeds, rates.trials, args.out);
  } catch (const std::exception& e) {
    std::cerr << "argus vision calibrate: " << e.what() << '\n';
    return run_failed;
  }
  return ok;
}

}  // namespace

/// Adds `argus vision localize` to `app`; its callback sets `result` to the exit code.
void add_vision_command(CLI::App& app, int& result) {
  auto* vision = app.add_subcommand(
      "vision", "Low-level visual routines on image files; emulated sensor calibration");
  vision->require_subcommand(1);
  auto args = std::make_shared<localize_arguments>();
  auto* cmd = vision->add_subcommand(
      "localize",
      "Localise every occurrence of a target patch's colours in an image (paper Fig. 9); "
      "prints a JSON array of {x, y, width, height, score} boxes in pixels");
  cmd->add_option("--image", args->image, "Image to search (any format OpenCV reads)")->required();
  cmd->add_option("--target", args->target, "Image of the target patch whose colours to find")
      ->required();
  cmd->add_option("--rho", args->rho, "Acceptance threshold on histogram intersection")
      ->check(number_in(0.0, 1.0));
  cmd->add_option("--single-scale", args->single_scale,
                  "Swain-Ballard single-scale localisation with kernel size L (pixels); overrides "
                  "--scales")
      ->check(integer_in(1, 100000));
  cmd->add_option("--scales", args->scales,
                  "Kernel sizes: 'target' (default: around the target patch's size, from half to "
                  "twice it), 'paper' ((0.1..1) x image height / 7, the paper's), or sizes L "
                  "such as 5,8,12 (kernels of 6L + 1 x 2L + 1 pixels)")
      ->check(kernel_scales_option());
  cmd->add_option("--max-regions", args->max_regions, "At most this many regions")
      ->check(integer_in(1, 1000000));
  cmd->callback([args, &result] { result = localize(*args); });

  auto calibration = std::make_shared<calibrate_arguments>();
  auto* fit = vision->add_subcommand(
      "calibrate",
      "Fit the emulated sensor's error model: render the scenario's cameras, run the pixel "
      "pipeline for every visible pedestrian beside the ground truth, write the model (YAML)");
  fit->add_option("SCENARIO", calibration->scenario, "Scenario YAML file")->required();
  fit->add_option("--start", calibration->start, "Virtual time of the first frame (default 30 s)");
  fit->add_option("--duration", calibration->duration, "Virtual time covered (default 60 s)");
  fit->add_option("--every", calibration->every, "Time between frames used (default 1 s)");
  fit->add_option("--cameras", calibration->cameras, "Use the first N cameras (default 4)")
      ->check(integer_in(1, 100000));
  fit->add_option("--width", calibration->width, "Image width (default 320)")
      ->check(integer_in(16, 8192));
  fit->add_option("--height", calibration->height, "Image height (default 240)")
      ->check(integer_in(16, 8192));
  fit->add_option("--seed", calibration->seed, "Run seed (default: the scenario's)")
      ->check(whole_number());
  fit->add_option("--field-of-view", calibration->field_of_view_deg,
                  "Horizontal field of view of every camera, degrees (default: each camera's "
                  "own); zoomed poses as when tracking")
      ->check(number_in(1.0, 179.0));
  fit->add_option("--scales", calibration->scales,
                  "Localiser kernel sizes: 'target' (default: around each pedestrian's size) or "
                  "'paper' (l = (0.1..1) x h / D; the default when --scale-divisor is given)")
      ->check(kernel_scales_option(false));
  fit->add_option("--scale-divisor", calibration->scale_divisor,
                  "With --scales paper: D (default 7, the paper's; larger for small "
                  "pedestrians)")
      ->check(number_in(1.0, 1000.0));
  fit->add_option("--seeds", calibration->seeds,
                  "Pool this many runs: the seed and the ones after it (default 1)")
      ->check(integer_in(1, 1000));
  fit->add_flag("--raw", calibration->raw,
                "Fit on undegraded frames: skip each camera's imaging model (colour response, "
                "noise, dropout, JPEG, interlacing)");
  fit->add_option("--out", calibration->out, "Model file to write (YAML)")->required();
  fit->callback([calibration, &result] { result = calibrate(*calibration); });
}

}  // namespace argus::apps
