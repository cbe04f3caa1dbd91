// `argus plan`: the station's plan view (paper Fig. 1) at a moment of a scenario's crowd.

#include <charconv>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "apps/commands.hpp"
#include "apps/output_file.hpp"
#include "apps/time_option.hpp"
#include "config/duration.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "config/ticks.hpp"
#include "fmt/format.h"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/plan_view.hpp"
#include "world/trajectory_writer.hpp"

namespace argus::apps {
namespace {

struct plan_arguments {
  std::string scenario;
  std::string time = "60 s";
  std::string trails = "10 s";
  std::string out;
};

int plan(const plan_arguments& args) {
  auto time_s = seconds_of(args.time);
  if (!time_s) {
    std::cerr << fmt::format(
        "argus plan: --time: expected a non-negative duration, e.g. '90 s' or '2 min', got "
        "'{}'\n",
        args.time);
    return bad_input;
  }
  auto trails_s = seconds_of(args.trails);
  if (!trails_s) {
    std::cerr << fmt::format(
        "argus plan: --trails: expected a non-negative duration, e.g. '10 s', got '{}'\n",
        args.trails);
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
    std::cerr << "argus plan: " << args.scenario << ": " << e.what() << '\n';
    return bad_input;
  }
  const double tick_s = scenario.run.tick.count();
  const auto ticks = config::to_ticks(config::seconds{*time_s}, scenario.run.tick);
  try {
    world::crowd crowd(station, world::crowd_settings::from(scenario));
    world::trail_recorder trails(std::chrono::duration<double>{*trails_s});
    trails.record(*crowd.current());
    for (std::int64_t k = 0; k < ticks; ++k) {
      crowd.step();
      trails.record(*crowd.current());
    }
    const std::filesystem::path png(args.out);
    make_parent_folders(png);
    world::write_plan_view(png, *station, scenario.cameras, crowd.current().get(),
                           *trails_s > 0.0 ? &trails.trails() : nullptr);
    std::cout << fmt::format("{}: plan view at t = {:.1f} s ({} pedestrians) written to {}\n",
                             scenario.name, static_cast<double>(ticks) * tick_s,
                             crowd.current()->pedestrians().size(), args.out);
  } catch (const std::invalid_argument& e) {
    std::cerr << "argus plan: " << e.what() << '\n';
    return bad_input;
  } catch (const config::scenario_error& e) {
    std::cerr << e.what() << '\n';
    return bad_input;
  } catch (const std::exception& e) {
    std::cerr << "argus plan: " << e.what() << '\n';
    return run_failed;
  }
  return ok;
}

}  // namespace

void add_plan_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "plan", "Draw the station's plan view with cameras, pedestrians and their trails (PNG)");
  auto args = std::make_shared<plan_arguments>();
  cmd->add_option("SCENARIO", args->scenario, "Scenario YAML file")->required();
  cmd->add_option("--time", args->time,
                  "Virtual time to step the crowd to, e.g. '90 s' (default 60 s)");
  cmd->add_option("--trails", args->trails,
                  "Length of the pedestrians' trails, e.g. '10 s'; 0 for none (default 10 s)");
  cmd->add_option("--out", args->out, "PNG file to write")->required();
  cmd->callback([args, &result] { result = plan(*args); });
}

}  // namespace argus::apps
