// `argus chaos`: runs a scenario under random fault schedules, one `argus run` process per
// seed, and checks every run's safety and liveness (docs/chaos.md).

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <thread>
#include <vector>

#include "actors/run_scenario.hpp"
#include "apps/chaos_plan.hpp"
#include "apps/child_process.hpp"
#include "apps/commands.hpp"
#include "apps/option_checks.hpp"
#include "apps/resume_record.hpp"
#include "apps/set_option.hpp"
#include "apps/sweep_progress.hpp"
#include "config/duration.hpp"
#include "config/enum_names.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "config/scenario_writer.hpp"
#include "fmt/format.h"
#include "report/binary_file.hpp"
#include "report/chaos_checks.hpp"
#include "world/layout_loader.hpp"

namespace argus::apps {
namespace {

struct chaos_arguments {
  std::string scenario;
  std::uint64_t seeds = 50;
  std::uint64_t first_seed = 1;
  std::vector<std::string> set;
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  std::optional<std::string> out;
  std::string duration = "3 min";
  std::uint64_t scenario_sensing_every = 10;
  std::uint64_t max_messages = 0;  // 0: 10 per camera of the scenario
  std::uint64_t max_memory_mib = 2048;
  double min_live_share = 0.99;
  bool keep = false;
  bool fresh = false;
  std::string program;
};

std::string seed_dir_name(std::uint64_t seed) {
  return fmt::format("seed-{}", seed);
}

nlohmann::json verdict_json(const apps::chaos_plan& plan, const report::chaos_verdict& v,
                            const report::chaos_bounds& bounds, int exit_status, double wall_s) {
  return {{"seed", plan.seed},
          {"merge", std::string(config::yaml_name(plan.merge))},
          {"sensing", std::string(config::yaml_name(plan.sensing))},
          {"nemeses", plan.nemeses},
          {"faults", plan.faults.size()},
          {"healed_at_s", plan.healed_at.count()},
          {"exit_status", exit_status},
          {"wall_s", wall_s},
          {"safe", v.safe(bounds)},
          {"live", v.live()},
          {"terms_broken", v.terms_broken},
          {"terms_reused_after_recovery", v.terms_reused_after_recovery},
          {"same_epoch_leaderships", v.same_epoch_leaderships},
          {"camera_in_two_groups", v.camera_in_two_groups},
          {"messages_after_cancel", v.messages_after_cancel},
          {"peak_messages_per_task_s", v.peak_messages_per_task_s},
          {"peak_rss_mib", v.peak_rss_kib / 1024.0},
          {"live_tasks", v.live_tasks},
          {"led_in_time", v.led_in_time},
          {"problems", v.problems}};
}

class campaign {
 public:
  campaign(const chaos_arguments& args, config::scenario scenario, apps::chaos_settings settings,
           report::chaos_bounds bounds, std::filesystem::path dir)
      : args_(args),
        scenario_(std::move(scenario)),
        settings_(settings),
        bounds_(bounds),
        dir_(std::move(dir)) {}

  int execute() {
    std::vector<std::uint64_t> to_do;
    for (auto s = args_.first_seed; s < args_.first_seed + args_.seeds; ++s)
      if (!report::read_json(dir_ / seed_dir_name(s) / "verdict.json").is_object())
        to_do.push_back(s);
    sweep_progress progress(args_.seeds, args_.seeds - to_do.size(), isatty(STDERR_FILENO) != 0);
    const std::string program = args_.program.empty() ? this_executable() : args_.program;
    struct running_run {
      apps::chaos_plan plan;
      std::chrono::steady_clock::time_point started;
    };
    std::map<pid_t, running_run> running;
    std::size_t next = 0;
    while (true) {
      while (running.size() < args_.jobs && next < to_do.size()) {
        auto plan = apps::plan_chaos(scenario_, to_do[next++], settings_);
        const auto dir = dir_ / seed_dir_name(plan.seed);
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        report::write_file(dir / "scenario.yaml",
                           config::to_yaml(apps::with_chaos(scenario_, plan, settings_)));
        const pid_t pid =
            start_process(program,
                          {"run", (dir / "scenario.yaml").string(), "--out", (dir / "run").string(),
                           "--no-progress", "--no-feeds", "--threads", "1"},
                          dir / "stdout.txt", dir / "stderr.txt");
        running[pid] = {std::move(plan), std::chrono::steady_clock::now()};
      }
      if (running.empty()) break;
      const auto ended = wait_for_any_child();
      if (!ended) continue;
      const auto it = running.find(ended->pid);
      if (it == running.end()) continue;
      const auto plan = std::move(it->second.plan);
      const double wall_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - it->second.started)
              .count();
      running.erase(it);
      const auto dir = dir_ / seed_dir_name(plan.seed);
      auto verdict =
          report::check_chaos_run(dir / "run", plan.healed_at.count(), bounds_, ended->max_rss_kib);
      if (ended->exit_status != 0) {
        verdict.complete = false;
        verdict.problems.push_back(fmt::format("argus run exited with {}", ended->exit_status));
      }
      const bool good = verdict.safe(bounds_) && verdict.live();
      report::write_file(
          dir / "verdict.json",
          verdict_json(plan, verdict, bounds_, ended->exit_status, wall_s).dump(1) + "\n");
      // A passing seed keeps its verdict and scenario; a failing one everything.
      if (good && !args_.keep) std::filesystem::remove_all(dir / "run");
      progress.run_ended(seed_dir_name(plan.seed), good ? 0 : 1, wall_s);
    }
    progress.finish();
    return summarise();
  }

 private:
  int summarise() const {
    nlohmann::json seeds = nlohmann::json::array();
    std::ofstream csv(dir_ / "chaos.csv");
    csv << "seed,merge,sensing,faults,safe,live,terms_broken,terms_reused_after_recovery,"
           "same_epoch_leaderships,"
           "camera_in_two_groups,messages_after_cancel,peak_messages_per_task_s,peak_rss_mib,"
           "live_tasks,led_in_time,wall_s\n";
    std::size_t done = 0, unsafe = 0, live_runs = 0, not_live = 0;
    std::uint64_t peak_messages = 0;
    double peak_memory = 0.0;
    std::vector<std::uint64_t> failing;
    for (auto s = args_.first_seed; s < args_.first_seed + args_.seeds; ++s) {
      const auto v = report::read_json(dir_ / seed_dir_name(s) / "verdict.json");
      if (!v.is_object()) continue;
      ++done;
      const bool safe = v.value("safe", false), live = v.value("live", false);
      unsafe += safe ? 0 : 1;
      if (v.value("live_tasks", 0) > 0) {
        ++live_runs;
        not_live += live ? 0 : 1;
      }
      if (!safe || !live) failing.push_back(s);
      peak_messages =
          std::max(peak_messages, v.value("peak_messages_per_task_s", std::uint64_t{0}));
      peak_memory = std::max(peak_memory, v.value("peak_rss_mib", 0.0));
      csv << fmt::format(
          "{},{},{},{},{},{},{},{},{},{},{},{},{:.1f},{},{},{:.2f}\n", s, v.value("merge", ""),
          v.value("sensing", ""), v.value("faults", 0), safe ? 1 : 0, live ? 1 : 0,
          v.value("terms_broken", 0), v.value("terms_reused_after_recovery", 0),
          v.value("same_epoch_leaderships", 0), v.value("camera_in_two_groups", 0),
          v.value("messages_after_cancel", 0), v.value("peak_messages_per_task_s", 0),
          v.value("peak_rss_mib", 0.0), v.value("live_tasks", 0), v.value("led_in_time", 0),
          v.value("wall_s", 0.0));
      seeds.push_back(v);
    }
    const double live_share =
        live_runs == 0 ? 1.0 : static_cast<double>(live_runs - not_live) / live_runs;
    const bool passed = done == args_.seeds && unsafe == 0 && live_share >= args_.min_live_share;
    const nlohmann::json summary = {{"scenario", args_.scenario},
                                    {"seeds", args_.seeds},
                                    {"first_seed", args_.first_seed},
                                    {"duration", args_.duration},
                                    {"bounds",
                                     {{"max_messages_per_task_s", bounds_.max_messages_per_task_s},
                                      {"max_memory_mib", bounds_.max_rss_kib / 1024},
                                      {"liveness_window_s", bounds_.liveness_window_s},
                                      {"min_live_share", args_.min_live_share}}},
                                    {"runs_checked", done},
                                    {"unsafe_runs", unsafe},
                                    {"runs_with_live_tasks", live_runs},
                                    {"runs_not_live", not_live},
                                    {"live_share", live_share},
                                    {"peak_messages_per_task_s", peak_messages},
                                    {"peak_memory_mib", peak_memory},
                                    {"failing_seeds", failing},
                                    {"passed", passed},
                                    {"runs", seeds}};
    report::write_file(dir_ / "chaos.json", summary.dump(1) + "\n");
    std::cout << fmt::format(
        "argus chaos: {} of {} seeds checked; safety broken in {}; liveness held in {} of {} runs "
        "with live tasks ({:.1f} %, needed {:.0f} %); peak {} messages per task per second "
        "(bound {}), peak memory {:.0f} MiB (bound {}); wrote {} and {}\n",
        done, args_.seeds, unsafe, live_runs - not_live, live_runs, 100.0 * live_share,
        100.0 * args_.min_live_share, peak_messages, bounds_.max_messages_per_task_s, peak_memory,
        bounds_.max_rss_kib / 1024, (dir_ / "chaos.json").string(), (dir_ / "chaos.csv").string());
    for (auto s : failing) {
      const auto v = report::read_json(dir_ / seed_dir_name(s) / "verdict.json");
      std::cout << fmt::format("seed {} failed:", s);
      for (const auto& p : v.value("problems", nlohmann::json::array()))
        std::cout << "\n  " << p.get<std::string>();
      std::cout << fmt::format("\n  reproduce: argus run {} --out {}\n",
                               (dir_ / seed_dir_name(s) / "scenario.yaml").string(),
                               (dir_ / seed_dir_name(s) / "again").string());
      // Every setting the seed's schedule and verdict depend on, into a folder of its own:
      // the campaign's folder would answer with the verdict it already has.
      std::cout << fmt::format(
          "  or: argus chaos {} --first-seed {} --seeds 1 --duration '{}' "
          "--scenario-sensing-every {} --max-messages {} --max-memory-mb {} --fresh --out {}",
          args_.scenario, s, args_.duration, args_.scenario_sensing_every,
          bounds_.max_messages_per_task_s, args_.max_memory_mib,
          (dir_ / fmt::format("again-seed-{}", s)).string());
      for (const auto& o : args_.set) std::cout << fmt::format(" --set '{}'", o);
      std::cout << '\n';
    }
    return passed ? ok : run_failed;
  }

  const chaos_arguments& args_;
  config::scenario scenario_;
  apps::chaos_settings settings_;
  report::chaos_bounds bounds_;
  std::filesystem::path dir_;
};

int run_chaos(const chaos_arguments& args) {
  const auto duration = config::parse_duration(args.duration);
  if (!duration || duration->count() <= 0.0) {
    std::cerr << fmt::format(
        "argus chaos: --duration: expected a positive duration with a unit, e.g. '3 min', got "
        "'{}'\n",
        args.duration);
    return bad_input;
  }
  apps::chaos_settings settings;
  settings.duration = *duration;
  settings.quiet_tail = config::seconds{std::min(40.0, duration->count() / 3.0)};
  settings.scenario_sensing_every = args.scenario_sensing_every;
  if (!args.program.empty() && access(args.program.c_str(), X_OK) != 0) {
    std::cerr << fmt::format("argus chaos: --argus: {} is not an executable file\n", args.program);
    return bad_input;
  }
  config::scenario scenario;
  try {
    scenario = config::load_scenario(args.scenario, overrides_from(args.set));
  } catch (const config::scenario_error& e) {
    std::cerr << e.what() << '\n';
    return bad_input;
  }
  // Each seed's scenario is written elsewhere: the files it names must be found from there.
  scenario.world.layout = std::filesystem::absolute(world::layout_path(scenario)).string();
  if (!scenario.sensing.sensor_model.empty())
    scenario.sensing.sensor_model =
        std::filesystem::absolute(actors::sensor_model_path(scenario)).string();
  if (scenario.cameras.empty()) {
    std::cerr << fmt::format("argus chaos: {}: cameras: expected at least one camera\n",
                             args.scenario);
    return bad_input;
  }
  report::chaos_bounds bounds;
  bounds.max_messages_per_task_s =
      args.max_messages > 0 ? args.max_messages : 10 * scenario.cameras.size();
  bounds.max_rss_kib = static_cast<long>(args.max_memory_mib * 1024);
  const auto dir = args.out ? std::filesystem::path(*args.out)
                            : std::filesystem::path("out") / ("chaos_" + scenario.name);
  try {
    std::filesystem::create_directories(dir);
    // Only what a campaign writes is ours to remove: --out may name a folder with more in it.
    std::vector<std::filesystem::path> ours;
    bool has_runs = false;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const auto name = entry.path().filename().string();
      const bool seed = entry.is_directory() && name.starts_with("seed-");
      if (seed || name == "chaos.json" || name == "chaos.csv" || name == made_with_file)
        ours.push_back(entry.path());
      has_runs = has_runs || seed;
    }
    if (args.fresh) {
      for (const auto& path : ours) std::filesystem::remove_all(path);
      has_runs = false;
    }
    // What a seed's verdict depends on besides the scenario: its schedule and the bounds.
    const nlohmann::json made_by{{"duration", args.duration},
                                 {"scenario_sensing_every", args.scenario_sensing_every},
                                 {"max_messages_per_task_s", bounds.max_messages_per_task_s},
                                 {"max_rss_kib", bounds.max_rss_kib}};
    const auto made = made_with(args.program.empty() ? this_executable() : args.program,
                                config::to_yaml(scenario), made_by);
    if (const auto refused = check_resume(dir, made, has_runs, "argus chaos")) {
      std::cerr << *refused << '\n';
      return bad_input;
    }
    return campaign(args, std::move(scenario), settings, bounds, dir).execute();
  } catch (const std::exception& e) {
    std::cerr << "argus chaos: " << e.what() << '\n';
    return run_failed;
  }
}

}  // namespace

void add_chaos_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "chaos",
      "Run a scenario under random fault schedules (loss bursts, delay spikes, partitions, "
      "crashes and recoveries, duplicates, reordering, cancellations) and check every run's "
      "safety and liveness");
  auto args = std::make_shared<chaos_arguments>();
  cmd->add_option("SCENARIO", args->scenario, "Scenario YAML file")->required();
  cmd->add_option("--seeds", args->seeds, "How many seeds (default 50)")
      ->check(integer_in(1, 100000));
  cmd->add_option("--first-seed", args->first_seed, "The first seed (default 1)")
      ->check(integer_in(1, 1000000000));
  add_set_option(cmd, args->set);
  cmd->add_option("--jobs", args->jobs, "Runs at once (default: one per core)")
      ->check(integer_in(1, 256));
  cmd->add_option("--out", args->out, "Campaign folder (default out/chaos_<scenario name>)");
  cmd->add_option("--duration", args->duration,
                  "Virtual duration of each run (default '3 min'); faults end 40 s before "
                  "(a third of it for shorter runs)");
  cmd->add_option("--scenario-sensing-every", args->scenario_sensing_every,
                  "Every K-th seed senses as the scenario says (pixels for the shipped ones), "
                  "the rest emulated (default 10; 0: all emulated; 1: all as the scenario)")
      ->check(integer_in(0, 1000000));
  cmd->add_option("--max-messages", args->max_messages,
                  "Bound on messages originated for one task in one simulated second (default "
                  "10 per camera of the scenario)")
      ->check(integer_in(1, 100000000));
  cmd->add_option("--max-memory-mb", args->max_memory_mib,
                  "Bound on each run's peak memory in MiB (default 2048)")
      ->check(integer_in(1, 1000000));
  cmd->add_option("--min-live", args->min_live_share,
                  "The share of runs with live tasks that must elect a leader in time (default "
                  "0.99)")
      ->check(number_in(0.0, 1.0));
  cmd->add_flag("--keep", args->keep, "Keep every run's folder (default: failing seeds' only)");
  cmd->add_flag("--fresh", args->fresh,
                "Remove the folder's earlier seeds first (a campaign resumes by default, and "
                "refuses a folder whose seeds another argus executable, scenario or setting "
                "made)");
  cmd->add_option("--argus", args->program,
                  "The argus executable the runs use (default: this one)");
  cmd->callback([args, &result] { result = run_chaos(*args); });
}

}  // namespace argus::apps
