#include <iostream>
#include <string>

#include "CLI/CLI.hpp"
#include "apps/allocator_settings.hpp"
#include "apps/commands.hpp"
#ifdef ARGUS_WITH_PYTHON
#include "python/embed.hpp"
#endif

namespace {

// The (sub)command whose arguments were being read: "argus run", "argus vision calibrate".
CLI::App* innermost_command(CLI::App& app) {
  CLI::App* at = &app;
  while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
  return at;
}

std::string command_path(CLI::App* command) {
  std::string path = command->get_name();
  for (auto* parent = command->get_parent(); parent != nullptr; parent = parent->get_parent())
    path = parent->get_name() + " " + path;
  return path;
}

// CLI11's message, or for a command given none of its subcommands, the ones it expects.
std::string message_of(const CLI::ParseError& e, CLI::App* command) {
  const auto subcommands = command->get_subcommands([](CLI::App*) { return true; });
  if (dynamic_cast<const CLI::RequiredError*>(&e) != nullptr &&
      command->get_require_subcommand_min() > 0 && !subcommands.empty()) {
    std::string names;
    for (const auto* sub : subcommands) names += (names.empty() ? "" : ", ") + sub->get_name();
    return "expected a command, one of " + names;
  }
  return e.what();
}

}  // namespace

int main(int argc, char** argv) {
  argus::apps::keep_freed_memory_mapped();
  CLI::App app{"argus: smart camera networks in virtual reality", "argus"};
  app.set_version_flag("--version", std::string("argus ") + ARGUS_VERSION);
  app.require_subcommand(1);
  int result = argus::apps::ok;
#ifdef ARGUS_WITH_PYTHON
  argus::pybridge::enable_embedded_python();
#endif
  argus::apps::add_run_command(app, result);
  argus::apps::add_serve_command(app, result);
  argus::apps::add_validate_command(app, result);
  argus::apps::add_strategies_command(app, result);
  argus::apps::add_plan_command(app, result);
  argus::apps::add_crowd_command(app, result);
  argus::apps::add_render_command(app, result);
  argus::apps::add_feeds_command(app, result);
  argus::apps::add_vision_command(app, result);
  argus::apps::add_csp_command(app, result);
  argus::apps::add_report_command(app, result);
  argus::apps::add_sweep_command(app, result);
  argus::apps::add_chaos_command(app, result);
  argus::apps::add_generate_command(app, result);
  argus::apps::add_worker_command(app, result);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    // Every other complaint of the parser (a value that does not convert or fails its check,
    // a missing or unexpected argument) is bad input: exit 2 like the commands' own checks.
    auto* command = innermost_command(app);
    const std::string path = command_path(command);
    std::cerr << path << ": " << message_of(e, command) << "\nRun '" << path
              << " --help' for the options.\n";
    return argus::apps::bad_input;
  }
  return result;
}
