#include <cstdio>
#include <iostream>

#include "apps/commands.hpp"
#include "apps/set_option.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "config/scenario_writer.hpp"
#include "controller/strategy_registry.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/station.hpp"

namespace argus::apps {

void add_validate_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "validate",
      "Check a scenario file and its station layout (every amenity reachable on foot from every "
      "entrance, lines on walkable floor, portals on the boundary, flows' exits) and print the "
      "effective configuration (defaults filled in) as YAML");
  auto path = std::make_shared<std::string>();
  auto set = std::make_shared<std::vector<std::string>>();
  cmd->add_option("SCENARIO", *path, "Scenario YAML file")->required();
  add_set_option(cmd, *set);
  cmd->callback([path, set, &result] {
    try {
      auto scenario = config::load_scenario(*path, overrides_from(*set));
      controller::resolve_strategy(scenario);
      // The layout is part of the input: the same bad layout fails here as in every command.
      const auto station = world::station::load(world::layout_path(scenario));
      (void)world::crowd_settings::from(scenario).spawning(*station);
      std::cout << config::to_yaml(scenario);
      result = ok;
    } catch (const config::scenario_error& e) {
      std::cerr << e.what() << '\n';
      result = bad_input;
    }
  });
}

}  // namespace argus::apps
