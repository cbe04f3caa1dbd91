// `argus strategies`: the camera strategies `controller.strategy` can name, built in and from
// plug-ins (docs/strategies.md).

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "controller/strategy_registry.hpp"
#include "fmt/format.h"
#include "nlohmann/json.hpp"

namespace argus::apps {

void add_strategies_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "strategies",
      "List the camera strategies controller.strategy can name: the built-in ones, those of "
      "the plug-ins given with --plugin and those ARGUS_STRATEGY_PLUGINS lists");
  auto plugins = std::make_shared<std::vector<std::string>>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("--plugin", *plugins, "A strategy plug-in (shared library) to load; repeatable");
  cmd->add_flag("--json", *json, "Print a JSON array instead of a table");
  cmd->callback([plugins, json, &result] {
    try {
      controller::load_listed_plugins();
      for (const auto& path : *plugins) controller::load_strategy_plugin(path);
    } catch (const std::runtime_error& e) {
      std::cerr << "argus strategies: " << e.what() << '\n';
      result = bad_input;
      return;
    }
    const auto entries = controller::registered_strategies();
    if (*json) {
      auto out = nlohmann::json::array();
      for (const auto& e : entries)
        out.push_back(
            {{"name", e.name}, {"oracle", e.oracle}, {"summary", e.summary}, {"source", e.source}});
      std::cout << out.dump(2) << '\n';
    } else {
      for (const auto& e : entries)
        std::cout << fmt::format("{:<18} {}{}\n{:<18} ({})\n", e.name, e.oracle ? "[oracle] " : "",
                                 e.summary, "", e.source);
    }
    result = ok;
  });
}

}  // namespace argus::apps
