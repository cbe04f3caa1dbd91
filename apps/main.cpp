#include <cstdio>

#include "CLI/CLI.hpp"
#include "apps/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"argus: smart camera networks in virtual reality", "argus"};
  app.set_version_flag("--version", std::string("argus ") + ARGUS_VERSION);
  app.require_subcommand(1);
  int result = argus::apps::ok;
  argus::apps::add_run_command(app, result);
  argus::apps::add_validate_command(app, result);
  argus::apps::add_plan_command(app, result);
  argus::apps::add_render_command(app, result);
  argus::apps::add_feeds_command(app, result);
  argus::apps::add_vision_command(app, result);
  argus::apps::add_csp_command(app, result);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  return result;
}
