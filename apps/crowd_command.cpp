// `argus crowd`: a scenario's crowd stepped alone, without cameras, for the standard
// experiments of pedestrian dynamics (scenarios/validation/): trajectories, the measurement
// areas' density, speed and flow, and how many left when.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>

#include "apps/commands.hpp"
#include "apps/set_option.hpp"
#include "apps/time_option.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "config/ticks.hpp"
#include "fmt/format.h"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/measurement.hpp"
#include "world/trajectory_writer.hpp"

namespace argus::apps {
namespace {

struct crowd_arguments {
  std::string scenario;
  std::string out;
  std::string duration;
  std::string every = "1 s";
  std::vector<std::string> set;
};

int step_crowd(const crowd_arguments& args) {
  const auto every_s = seconds_of(args.every);
  if (!every_s || *every_s <= 0.0) {
    std::cerr << fmt::format(
        "argus crowd: --every: expected a positive duration, e.g. '0.5 s', got '{}'\n", args.every);
    return bad_input;
  }
  std::optional<double> duration_s;
  if (!args.duration.empty()) {
    duration_s = seconds_of(args.duration);
    if (!duration_s) {
      std::cerr << fmt::format(
          "argus crowd: --duration: expected a non-negative duration, e.g. '90 s', got '{}'\n",
          args.duration);
      return bad_input;
    }
  }
  config::scenario scenario;
  std::shared_ptr<const world::station> station;
  std::optional<world::crowd> crowd;
  try {
    scenario = config::load_scenario(args.scenario, overrides_from(args.set));
    station = world::station::load(world::layout_path(scenario));
    crowd.emplace(station, world::crowd_settings::from(scenario));
  } catch (const config::scenario_error& e) {
    std::cerr << e.what() << '\n';
    return bad_input;
  }
  if (duration_s) scenario.run.duration = config::seconds{*duration_s};
  const std::filesystem::path dir(args.out);
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  // Written under .partial names and renamed at the end: nothing half-written is left.
  const auto trajectories_file = dir / "trajectories.csv";
  const auto measurements_file = dir / "measurements.csv";
  std::ofstream trajectories(trajectories_file.string() + ".partial");
  std::ofstream measurements(measurements_file.string() + ".partial");
  if (!trajectories || !measurements) {
    std::cerr << fmt::format("argus crowd: cannot write into {}\n", dir.string());
    return run_failed;
  }
  std::vector<world::named_area> areas;
  for (const auto& a : scenario.world.measurement_areas) {
    areas.push_back({a.name, {{a.area.min_x_m, a.area.min_y_m}, {a.area.max_x_m, a.area.max_y_m}}});
  }
  world::trajectory_writer trajectory_rows(trajectories);
  world::measurement_writer measurement_rows(measurements);
  const auto ticks = config::to_ticks(scenario.run.duration, scenario.run.tick);
  const auto sample_every =
      std::max<std::int64_t>(1, config::to_ticks(config::seconds{*every_s}, scenario.run.tick));
  std::size_t spawned = 0;
  std::size_t left = 0;
  double last_left_s = 0.0;
  trajectory_rows.write(*crowd->current());
  for (std::int64_t k = 1; k <= ticks; ++k) {
    crowd->step();
    const auto& frame = *crowd->current();
    trajectory_rows.write(frame);
    if (k % sample_every == 0) measurement_rows.write(frame, areas);
    for (const auto& e : frame.events()) {
      if (e.kind == world::event_kind::spawned) ++spawned;
      if (e.kind == world::event_kind::left) {
        ++left;
        last_left_s = frame.time().count();
      }
    }
  }
  trajectories.close();
  measurements.close();
  std::filesystem::rename(trajectories_file.string() + ".partial", trajectories_file, error);
  std::filesystem::rename(measurements_file.string() + ".partial", measurements_file, error);
  if (error) {
    std::cerr << fmt::format("argus crowd: cannot write into {}: {}\n", dir.string(),
                             error.message());
    return run_failed;
  }
  std::cout << fmt::format(
      "{}: {:.1f} s, {} pedestrians entered, {} left (the last at {:.1f} s), {} still inside\n"
      "  trajectories: {}\n  measurements: {}\n",
      scenario.name, static_cast<double>(ticks) * scenario.run.tick.count(), spawned, left,
      last_left_s, crowd->current()->pedestrians().size(), trajectories_file.string(),
      measurements_file.string());
  return ok;
}

}  // namespace

void add_crowd_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "crowd",
      "Step a scenario's crowd alone (no cameras): trajectories.csv, the measurement areas' "
      "density, speed and flow in measurements.csv, and who left when");
  auto args = std::make_shared<crowd_arguments>();
  cmd->add_option("SCENARIO", args->scenario, "Scenario YAML file")->required();
  cmd->add_option("--out", args->out, "Output directory")->required();
  cmd->add_option("--duration", args->duration,
                  "Virtual duration, e.g. '90 s' (default: the scenario's run.duration)");
  cmd->add_option("--every", args->every,
                  "Interval between measurement rows, e.g. '0.5 s' (default 1 s)");
  add_set_option(cmd, args->set);
  cmd->callback([args, &result] { result = step_crowd(*args); });
}

}  // namespace argus::apps
