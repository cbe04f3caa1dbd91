#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <tuple>
#include <utility>

#include "actors/run_scenario.hpp"
#include "actors/worker_pool.hpp"
#include "apps/commands.hpp"
#include "apps/option_checks.hpp"
#include "apps/run_overrides.hpp"
#include "apps/run_record.hpp"
#include "apps/set_option.hpp"
#include "apps/task_option.hpp"
#include "apps/tls_options.hpp"
#include "apps/workers_option.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "eval/run_files.hpp"
#include "fmt/format.h"
#include "live/command_log.hpp"
#include "nlohmann/json.hpp"

namespace argus::apps {
namespace {

struct run_arguments {
  std::string scenario;
  run_overrides overrides;
  std::vector<std::string> set;
  bool json = false;
  bool no_progress = false;
  bool video = false;
  std::string video_size = "320x240";
  bool mot = false;
  bool no_feeds = false;
  std::vector<std::string> tasks;
  std::optional<std::string> commands;
  workers_arguments workers;
  tls_arguments tls;
};

// `--video-size WxH`, each side 16 to 4096 pixels.
std::pair<int, int> parse_video_size(const std::string& text) {
  int width = 0;
  int height = 0;
  char x = 0;
  char rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &rest) != 3 ||
      (x != 'x' && x != 'X') || width < 16 || width > 4096 || height < 16 || height > 4096)
    throw CLI::ValidationError(
        "--video-size",
        fmt::format("expected WIDTHxHEIGHT, 16 to 4096 pixels each, e.g. 320x240, got '{}'", text));
  return {width, height};
}

void print_outcome(const run_arguments& args, const config::scenario& s,
                   const actors::run_outcome& outcome,
                   const std::optional<std::filesystem::path>& report) {
  const auto& r = outcome.result;
  if (args.json) {
    nlohmann::json j;
    j["scenario"] = s.name;
    j["seed"] = s.run.seed;
    j["ticks"] = r.ticks;
    j["virtual_seconds"] = r.virtual_seconds;
    j["wall_seconds"] = r.wall_seconds;
    j["events_total"] = r.events_total;
    j["events_by_kind"] = r.events_by_kind;
    j["unexpected_down"] = r.unexpected_down;
    if (!r.lost_workers.empty()) j["lost_workers"] = r.lost_workers;
    j["events"] = (outcome.output_dir / "events.jsonl").string();
    j["summary"] = (outcome.output_dir / "summary.json").string();
    j["metrics"] = (outcome.output_dir / "metrics.json").string();
    if (args.video) j["video"] = (outcome.output_dir / "video" / "feeds.avi").string();
    if (report) j["report"] = report->string();
    if (report && std::filesystem::exists(outcome.output_dir / "feeds" / "contact_sheet.png"))
      j["feeds"] = (outcome.output_dir / "feeds").string();
    std::cout << j.dump() << '\n';
    return;
  }
  std::cout << fmt::format(
      "{}: {} ticks, {:.1f} s simulated in {:.2f} s wall ({:.1f}x real time), {} events\n", s.name,
      r.ticks, r.virtual_seconds, r.wall_seconds,
      r.wall_seconds > 0 ? r.virtual_seconds / r.wall_seconds : 0.0, r.events_total);
  std::cout << "  events:  " << (outcome.output_dir / "events.jsonl").string() << '\n';
  std::cout << "  summary: " << (outcome.output_dir / "summary.json").string() << '\n';
  std::cout << "  metrics: " << (outcome.output_dir / "metrics.json").string() << '\n';
  if (args.mot) std::cout << "  mot:     " << (outcome.output_dir / "mot").string() << '\n';
  eval::print_metrics_table(std::cout, outcome.evaluation);
  if (args.video)
    std::cout << "  video:   " << (outcome.output_dir / "video" / "feeds.avi").string() << '\n';
  if (report && std::filesystem::exists(outcome.output_dir / "feeds" / "contact_sheet.png"))
    std::cout << "  feeds:   " << (outcome.output_dir / "feeds").string() << '\n';
  if (report) std::cout << "  report:  " << report->string() << '\n';
  if (!r.unexpected_down.empty())
    std::cout << "  participants that died unexpectedly: " << r.unexpected_down.size() << '\n';
  for (const auto& lost : r.lost_workers)
    std::cout << "  worker lost, its cameras crashed: " << lost << '\n';
}

}  // namespace

void add_run_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand("run", "Run a scenario and write its event log and summary");
  auto args = std::make_shared<run_arguments>();
  cmd->add_option("SCENARIO", args->scenario, "Scenario YAML file")->required();
  add_run_override_options(cmd, args->overrides);
  add_set_option(cmd, args->set);
  cmd->add_flag("--json", args->json, "Print the outcome as one JSON object");
  cmd->add_flag("--no-progress", args->no_progress, "No progress line, even on a terminal");
  cmd->add_flag("--video", args->video,
                "Also write a mosaic video of every camera's view to DIR/video/feeds.avi");
  cmd->add_option("--video-size", args->video_size,
                  "Size of one camera's tile in the video, WxH (default 320x240)");
  cmd->add_flag("--mot", args->mot,
                "Also write ground truth and track boxes in MOTChallenge format to DIR/mot");
  cmd->add_flag("--no-feeds", args->no_feeds,
                "Leave out DIR/feeds/ (the cameras' frames at the key events, rendered again after "
                "the run) and its contact sheet in report.html");
  cmd->add_option("--task", args->tasks,
                  "Add an operator task, e.g. 'at=10s,camera=7,pixel=160x120' (repeatable; keys "
                  "as in a scenario's tasks)");
  add_workers_options(cmd, args->workers);
  add_tls_options(cmd, args->tls, "coordinator", "worker");
  cmd->add_option("--commands", args->commands,
                  "Replay the operator's commands of a live run (DIR/commands.yaml of argus "
                  "serve) at the ticks they took effect");
  cmd->callback([args, &result] {
    config::scenario scenario;
    try {
      scenario = load_with_tasks(args->scenario, overrides_from(args->set), args->tasks);
    } catch (const config::scenario_error& e) {
      std::cerr << e.what() << '\n';
      result = bad_input;
      return;
    }
    apply_run_overrides(args->overrides, scenario);
    if (args->commands) {
      try {
        live::apply_commands(scenario, live::read_commands(*args->commands));
      } catch (const std::exception& e) {
        std::cerr << "argus run: --commands: " << e.what() << '\n';
        result = bad_input;
        return;
      }
    }
    actors::run_options options;
    try {
      apply_workers_options(args->workers, args->tls, /*tls_only_for_workers=*/true, options);
    } catch (const std::invalid_argument& e) {
      std::cerr << "argus run: " << e.what() << '\n';
      result = bad_input;
      return;
    }
    std::tie(options.video_width_px, options.video_height_px) = parse_video_size(args->video_size);
    options.video = args->video;
    options.mot = args->mot;
    try {
      options.show_progress = !args->no_progress && isatty(STDERR_FILENO) != 0;
      auto outcome = actors::run_scenario(scenario, options);
      const auto report =
          record_run(scenario, outcome.output_dir, !args->no_feeds, outcome.station);
      print_outcome(*args, scenario, outcome, report);
      result = ok;
      // A strategy that raised ended the run early: its outputs are complete up to that tick.
      if (!outcome.result.failure.empty()) {
        std::cerr << "argus run: " << outcome.result.failure << '\n';
        result = run_failed;
      }
    } catch (const config::scenario_error& e) {
      // A bad layout (or a flow naming no portal) is bad input, as in validate, plan and feeds.
      std::cerr << e.what() << '\n';
      result = bad_input;
    } catch (const std::exception& e) {
      std::cerr << "argus run: " << e.what() << '\n';
      result = run_failed;
    }
  });
}

}  // namespace argus::apps
