// `argus render`: one camera's synthetic video frame at a moment of a scenario (Section III-A).

#include <charconv>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
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
#include "vision/imaging_model.hpp"
#include "vision/renderer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::apps {

void add_render_command(CLI::App& app, int& result);

namespace {

struct render_arguments {
  std::string scenario;
  int camera = 0;
  std::string time = "60 s";
  bool raw = false;
  std::optional<int> width;
  std::optional<int> height;
  std::string out;
};

int render(const render_arguments& args) {
  auto time_s = seconds_of(args.time);
  if (!time_s) {
    std::cerr << fmt::format(
        "argus render: --time: expected a non-negative duration, e.g. '90 s', got '{}'\n",
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
    std::cerr << "argus render: " << args.scenario << ": " << e.what() << '\n';
    return bad_input;
  }
  const config::camera_settings* camera = nullptr;
  for (const auto& c : scenario.cameras) {
    if (c.id == args.camera) camera = &c;
  }
  if (camera == nullptr) {
    std::string ids;
    for (const auto& c : scenario.cameras) ids += (ids.empty() ? "" : ", ") + std::to_string(c.id);
    std::cerr << fmt::format("argus render: --camera: no camera {} in {} (cameras: {})\n",
                             args.camera, args.scenario, ids.empty() ? "none" : ids);
    return bad_input;
  }
  try {
    const double tick_s = scenario.run.tick.count();
    const auto ticks = config::to_ticks(config::seconds{*time_s}, scenario.run.tick);
    world::crowd crowd(station, world::crowd_settings::from(scenario));
    for (std::int64_t k = 0; k < ticks; ++k) crowd.step();
    const double t = static_cast<double>(ticks) * tick_s;

    config::imaging_model imaging = camera->imaging;
    if (args.width) imaging.width_px = static_cast<unsigned>(*args.width);
    if (args.height) imaging.height_px = static_cast<unsigned>(*args.height);
    vision::camera_view view{
        vision::camera_placement::from(*camera), vision::ptz_camera::from(*camera).state(),
        static_cast<int>(imaging.width_px), static_cast<int>(imaging.height_px)};
    vision::renderer renderer(station);
    const auto& frame = *crowd.current();
    cv::Mat image;
    if (args.raw) {
      image = renderer.render(view, frame, t);
    } else {
      auto model = vision::imaging_model::for_camera(imaging, scenario.run.seed, camera->id);
      // The second field is rendered half a frame later; pedestrians stand where the
      // snapshot has them (the crowd steps once per frame), only their gait moves on.
      image = vision::capture(renderer, view, frame, t, tick_s / 2.0, model);
    }
    make_parent_folders(args.out);
    if (!cv::imwrite(args.out, image)) {
      std::cerr << fmt::format("argus render: cannot write {}\n", args.out);
      return run_failed;
    }
    std::cout << fmt::format("{}: camera {} at t = {:.2f} s ({}x{}, {}) written to {} [{}]\n",
                             scenario.name, camera->id, t, view.width_px, view.height_px,
                             args.raw ? "raw" : "imaging model", args.out, renderer.device());
  } catch (const config::scenario_error& e) {
    std::cerr << e.what() << '\n';
    return bad_input;
  } catch (const std::exception& e) {
    std::cerr << "argus render: " << e.what() << '\n';
    return run_failed;
  }
  return ok;
}

}  // namespace

void add_render_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "render", "Render one camera's synthetic video frame at a moment of the scenario (PNG)");
  auto args = std::make_shared<render_arguments>();
  cmd->add_option("SCENARIO", args->scenario, "Scenario YAML file")->required();
  cmd->add_option("--camera", args->camera, "Camera id")
      ->required()
      ->check(integer_in(INT32_MIN, INT32_MAX));
  cmd->add_option("--time", args->time,
                  "Virtual time to step the crowd to, e.g. '90 s' (default 60 s)");
  cmd->add_flag("--raw", args->raw, "Skip the imaging model (colour response, noise, JPEG...)");
  cmd->add_option("--width", args->width, "Image width in pixels (default: the camera's)")
      ->check(integer_in(16, 8192));
  cmd->add_option("--height", args->height, "Image height in pixels (default: the camera's)")
      ->check(integer_in(16, 8192));
  cmd->add_option("--out", args->out, "Image file to write (PNG)")->required();
  cmd->callback([args, &result] { result = render(*args); });
}

}  // namespace argus::apps
