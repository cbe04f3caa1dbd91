// `argus report DIR`: (re)builds a run's pictures, key frames and page from its output folder.

#include <filesystem>
#include <iostream>
#include <optional>

#include "apps/commands.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "report/build_reports.hpp"

namespace argus::apps {
namespace {

struct report_arguments {
  std::string dir;
  std::string scenario;
  bool no_feeds = false;
};

int report(const report_arguments& args) {
  if (!std::filesystem::is_directory(args.dir)) {
    std::cerr << "argus report: " << args.dir
              << ": not a folder (expected a run's output folder)\n";
    return bad_input;
  }
  std::optional<config::scenario> scenario;
  if (!args.scenario.empty()) {
    try {
      scenario = config::load_scenario(args.scenario);
    } catch (const config::scenario_error& e) {
      std::cerr << e.what() << '\n';
      return bad_input;
    }
  }
  try {
    report::report_options options;
    options.feeds = !args.no_feeds;
    const auto outcome = report::build_reports(args.dir, scenario ? &*scenario : nullptr, options);
    for (const auto& file : outcome.written) std::cout << "  wrote " << file.string() << '\n';
    for (const auto& note : outcome.left_out) std::cout << "  left out: " << note << '\n';
  } catch (const std::exception& e) {
    std::cerr << "argus report: " << e.what() << '\n';
    return run_failed;
  }
  return ok;
}

}  // namespace

void add_report_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "report",
      "Draw a run's plan.png, timeline.png, feeds/ and report.html from its output folder");
  auto args = std::make_shared<report_arguments>();
  cmd->add_option("DIR", args->dir, "The run's output folder")->required();
  cmd->add_option(
      "--scenario", args->scenario,
      "Scenario file for the plan (default: DIR/scenario.yaml, which argus run writes)");
  cmd->add_flag("--no-feeds", args->no_feeds,
                "Leave DIR/feeds/ as it is: draw no frames at the key events (they render)");
  cmd->callback([args, &result] { result = report(*args); });
}

}  // namespace argus::apps
