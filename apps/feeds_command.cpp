// `argus feeds`: a mosaic of every camera's synthetic video at a moment of a scenario (the
// paper's Fig. 3).

#include <algorithm>
#include <charconv>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <stdexcept>

#include "CLI/CLI.hpp"
#include "apps/commands.hpp"
#include "apps/option_checks.hpp"
#include "apps/output_file.hpp"
#include "apps/time_option.hpp"
#include "config/duration.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "config/ticks.hpp"
#include "fmt/format.h"
#include "vision/capture.hpp"
#include "vision/feed_mosaic.hpp"
#include "vision/imaging_model.hpp"
#include "vision/renderer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::apps {

void add_feeds_command(CLI::App& app, int& result);

namespace {

struct feeds_arguments {
  std::string scenario;
  std::string time = "60 s";
  bool raw = false;
  int width = 320;
  int height = 240;
  std::string out;
};

int feeds(const feeds_arguments& args) {
  auto time_s = seconds_of(args.time);
  if (!time_s) {
    std::cerr << fmt::format(
        "argus feeds: --time: expected a non-negative duration, e.g. '90 s', got '{}'\n",
        args.time);
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
    std::cerr << "argus feeds: " << args.scenario << ": " << e.what() << '\n';
    return bad_input;
  }
  if (scenario.cameras.empty()) {
    std::cerr << fmt::format("argus feeds: {} has no cameras\n", args.scenario);
    return bad_input;
  }
  try {
    const double tick_s = scenario.run.tick.count();
    const auto ticks = config::to_ticks(config::seconds{*time_s}, scenario.run.tick);
    world::crowd crowd(station, world::crowd_settings::from(scenario));
    for (std::int64_t k = 0; k < ticks; ++k) crowd.step();
    const double t = static_cast<double>(ticks) * tick_s;
    const auto& frame = *crowd.current();

    auto cameras = scenario.cameras;
    std::sort(cameras.begin(), cameras.end(),
              [](const auto& a, const auto& b) { return a.id < b.id; });
    const int n = static_cast<int>(cameras.size());
    const auto layout =
        vision::feed_mosaic_layout::for_feeds(cameras.size(), args.width, args.height);
    cv::Mat mosaic(layout.size(), CV_8UC3, cv::Scalar(0, 0, 0));
    vision::renderer renderer(station);
    for (int k = 0; k < n; ++k) {
      const auto& camera = cameras[static_cast<std::size_t>(k)];
      vision::camera_view view{vision::camera_placement::from(camera),
                               vision::ptz_camera::from(camera).state(), args.width, args.height};
      cv::Mat tile;
      if (args.raw) {
        tile = renderer.render(view, frame, t);
      } else {
        config::imaging_model imaging = camera.imaging;
        imaging.width_px = static_cast<unsigned>(args.width);
        imaging.height_px = static_cast<unsigned>(args.height);
        auto model = vision::imaging_model::for_camera(imaging, scenario.run.seed, camera.id);
        tile = vision::capture(renderer, view, frame, t, tick_s / 2.0, model);
      }
      vision::label_feed(tile, camera.id);
      tile.copyTo(mosaic(layout.tile(static_cast<std::size_t>(k))));
    }
    make_parent_folders(args.out);
    if (!cv::imwrite(args.out, mosaic)) {
      std::cerr << fmt::format("argus feeds: cannot write {}\n", args.out);
      return run_failed;
    }
    std::cout << fmt::format("{}: {} camera feeds at t = {:.2f} s ({}x{} each) written to {}\n",
                             scenario.name, n, t, args.width, args.height, args.out);
  } catch (const config::scenario_error& e) {
    std::cerr << e.what() << '\n';
    return bad_input;
  } catch (const std::exception& e) {
    std::cerr << "argus feeds: " << e.what() << '\n';
    return run_failed;
  }
  return ok;
}

}  // namespace

void add_feeds_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "feeds", "Render every camera's view at a moment of the scenario as one mosaic (PNG)");
  auto args = std::make_shared<feeds_arguments>();
  cmd->add_option("SCENARIO", args->scenario, "Scenario YAML file")->required();
  cmd->add_option("--time", args->time,
                  "Virtual time to step the crowd to, e.g. '90 s' (default 60 s)");
  cmd->add_flag("--raw", args->raw, "Skip the imaging model");
  cmd->add_option("--width", args->width, "Width of one camera's tile (default 320)")
      ->check(integer_in(16, 4096));
  cmd->add_option("--height", args->height, "Height of one camera's tile (default 240)")
      ->check(integer_in(16, 4096));
  cmd->add_option("--out", args->out, "Image file to write (PNG)")->required();
  cmd->callback([args, &result] { result = feeds(*args); });
}

}  // namespace argus::apps
