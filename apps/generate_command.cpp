#include <filesystem>
#include <iostream>
#include <memory>
#include <ostream>

#include "apps/commands.hpp"
#include "apps/generated_station.hpp"
#include "apps/option_checks.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "config/whole_file.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/station.hpp"

namespace argus::apps {
namespace {

struct generate_options {
  station_plan plan;
  std::string out;
};

int generate(const generate_options& o) {
  if (o.plan.tasks > o.plan.cameras) {
    std::cerr << "argus generate station: --tasks: expected at most --cameras (" << o.plan.cameras
              << "), got " << o.plan.tasks << '\n';
    return bad_input;
  }
  const std::filesystem::path scenario_file(o.out);
  if (scenario_file.extension() != ".yaml") {
    std::cerr << "argus generate station: --out: expected a .yaml file, got '" << o.out << "'\n";
    return bad_input;
  }
  const auto layout_name = scenario_file.stem().string() + "_layout.yaml";
  const auto layout_file = scenario_file.parent_path() / layout_name;
  auto plan = o.plan;
  plan.name = scenario_file.stem().string();
  const auto files = generate_station(plan, layout_name);
  try {
    if (!scenario_file.parent_path().empty())
      std::filesystem::create_directories(scenario_file.parent_path());
    config::write_whole_file(layout_file, [&](std::ostream& s) { s << files.layout_yaml; });
    config::write_whole_file(scenario_file, [&](std::ostream& s) { s << files.scenario_yaml; });
    // What was written must load: a generator that writes a station no command can run is a
    // bug, not bad input.
    const auto scenario = config::load_scenario(scenario_file);
    const auto station = world::station::load(world::layout_path(scenario));
    (void)world::crowd_settings::from(scenario).spawning(*station);
  } catch (const config::scenario_error& e) {
    std::cerr << "argus generate station: the generated files do not load:\n" << e.what() << '\n';
    return run_failed;
  } catch (const std::exception& e) {
    std::cerr << "argus generate station: " << e.what() << '\n';
    return run_failed;
  }
  std::cout << "station: " << plan.halls_east << " x " << plan.halls_north << " halls, "
            << plan.cameras << " cameras, " << plan.pedestrians << " pedestrians, " << plan.tasks
            << " tasks\n  scenario: " << scenario_file.string()
            << "\n  layout:   " << layout_file.string() << '\n';
  return ok;
}

}  // namespace

void add_generate_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand("generate", "Generate scenario files");
  cmd->require_subcommand(1);
  auto* station = cmd->add_subcommand(
      "station",
      "A large station: a grid of 100 m x 60 m halls, cameras spread evenly, emulated sensing "
      "(writes FILE.yaml and FILE_layout.yaml beside it)");
  auto o = std::make_shared<generate_options>();
  station->add_option("--halls-east", o->plan.halls_east, "Halls from west to east (default 8)")
      ->check(integer_in(1, 64));
  station->add_option("--halls-north", o->plan.halls_north, "Halls from south to north (default 4)")
      ->check(integer_in(1, 64));
  station->add_option("--cameras", o->plan.cameras, "Cameras (default 1024)")
      ->check(integer_in(1, 65535));
  station->add_option("--pedestrians", o->plan.pedestrians, "Population (default 10000)")
      ->check(integer_in(1, 1000000));
  station
      ->add_option("--tasks", o->plan.tasks, "Tasks, each on a camera's next entrant (default 16)")
      ->check(integer_in(0, 65535));
  station->add_option("--partitions", o->plan.partitions, "Crowd partitions (default 8)")
      ->check(integer_in(1, 256));
  station->add_option("--out", o->out, "Scenario file to write (.yaml)")->required();
  station->callback([o, &result] { result = generate(*o); });
}

}  // namespace argus::apps
