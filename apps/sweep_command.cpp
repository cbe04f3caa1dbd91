// `argus sweep`: a grid of scenario overrides over seeds, each run an `argus run` process,
// several at once; results in sweep.csv, sweep.json and plots (docs/sweep.md).

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <fstream>
#include <iostream>
#include <map>
#include <thread>

#include "apps/child_process.hpp"
#include "apps/commands.hpp"
#include "apps/option_checks.hpp"
#include "apps/resume_record.hpp"
#include "apps/sweep_progress.hpp"
#include "config/duration.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "config/scenario_writer.hpp"
#include "controller/strategy_registry.hpp"
#include "fmt/format.h"
#include "report/binary_file.hpp"
#include "report/paired_differences.hpp"
#include "report/sweep_grid.hpp"
#include "report/sweep_outputs.hpp"

namespace argus::apps {
namespace {

struct sweep_arguments {
  std::string scenario;
  std::uint64_t seeds = 1;
  std::uint64_t first_seed = 1;
  std::vector<std::string> set;
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  unsigned threads = 1;
  std::optional<std::string> out;
  std::optional<std::string> duration;
  std::string program;
  bool feeds = false;
  bool fresh = false;
  std::string compare = "mean_coverage";
  double equal_within = 0.0;
};

// Children the signal handler stops; slots hold 0 when free. A handler may only call
// async-signal-safe functions: kill() is one.
constexpr std::size_t max_jobs = 256;
pid_t running_children[max_jobs] = {};
volatile std::sig_atomic_t interrupted = 0;

extern "C" void on_interrupt(int) {
  interrupted = 1;
  for (pid_t pid : running_children)
    if (pid > 0) kill(pid, SIGTERM);
}

void install_interrupt_handler() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: the wait for a child returns at once
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

// A run is done when its metrics.json is whole: it parses and has its summary.
bool finished(const std::filesystem::path& run_dir) {
  const auto metrics = report::read_json(run_dir / "metrics.json");
  return metrics.is_object() && metrics.contains("summary") && metrics["summary"].is_object();
}

std::vector<config::field_override> overrides_of(const std::vector<report::swept_parameter>& ps,
                                                 const report::planned_run& run) {
  std::vector<config::field_override> out;
  for (std::size_t k = 0; k < ps.size(); ++k) out.push_back({ps[k].key, run.values[k]});
  return out;
}

std::vector<std::string> run_arguments(const sweep_arguments& args,
                                       const std::vector<report::swept_parameter>& parameters,
                                       const report::planned_run& run,
                                       const std::filesystem::path& run_dir) {
  std::vector<std::string> out{"run",
                               args.scenario,
                               "--seed",
                               std::to_string(run.seed),
                               "--out",
                               run_dir.string(),
                               "--no-progress",
                               "--threads",
                               std::to_string(args.threads)};
  for (const auto& o : overrides_of(parameters, run)) {
    out.push_back("--set");
    out.push_back(o.path + "=" + o.value);
  }
  if (args.duration) {
    out.push_back("--duration");
    out.push_back(*args.duration);
  }
  // A sweep measures; the key frames of every run would cost it rendering nobody looks at.
  if (!args.feeds) out.push_back("--no-feeds");
  return out;
}

class sweep {
 public:
  sweep(const sweep_arguments& args, std::vector<report::swept_parameter> parameters,
        std::filesystem::path dir)
      : args_(args), parameters_(std::move(parameters)), dir_(std::move(dir)) {
    runs_ = report::plan_runs(parameters_, args.seeds, args.first_seed);
  }

  int execute() {
    std::vector<const report::planned_run*> to_do;
    for (const auto& run : runs_)
      if (!finished(run_dir(run))) to_do.push_back(&run);
    sweep_progress progress(runs_.size(), runs_.size() - to_do.size(), isatty(STDERR_FILENO) != 0);
    install_interrupt_handler();
    const std::string program = args_.program.empty() ? this_executable() : args_.program;
    std::map<pid_t, std::pair<const report::planned_run*, std::chrono::steady_clock::time_point>>
        running;
    std::size_t next = 0;
    while (true) {
      while (!interrupted && running.size() < args_.jobs && next < to_do.size()) {
        const auto& run = *to_do[next++];
        const auto dir = run_dir(run);
        std::filesystem::create_directories(dir);
        std::filesystem::remove(dir / "sweep_run.json");
        const pid_t pid = start_process(program, run_arguments(args_, parameters_, run, dir),
                                        dir / "stdout.txt", dir / "stderr.txt");
        running[pid] = {&run, std::chrono::steady_clock::now()};
        slot(0, pid);
      }
      if (running.empty()) break;
      const auto ended = wait_for_any_child();
      if (!ended) continue;  // a signal: the loop starts nothing more, and waits for the rest
      const auto it = running.find(ended->pid);
      if (it == running.end()) continue;
      slot(ended->pid, 0);
      const auto [run, started] = it->second;
      running.erase(it);
      if (interrupted) continue;  // stopped by us: no record, so a resume redoes it
      const double wall_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      report::write_file(
          run_dir(*run) / "sweep_run.json",
          nlohmann::json{{"exit_status", ended->exit_status}, {"wall_s", wall_s}}.dump() + "\n");
      progress.run_ended(run->id, ended->exit_status, wall_s);
    }
    progress.finish();
    return summarise();
  }

 private:
  std::filesystem::path run_dir(const report::planned_run& run) const {
    return dir_ / "runs" / run.id;
  }

  static void slot(pid_t from, pid_t to) {
    for (auto& pid : running_children)
      if (pid == from) {
        pid = to;
        return;
      }
  }

  int summarise() {
    report::sweep_results results;
    results.scenario = args_.scenario;
    results.parameters = parameters_;
    results.seeds = args_.seeds;
    results.equal_within = args_.equal_within;
    results.compare = args_.compare;
    std::size_t failed = 0;
    std::size_t missing = 0;
    for (const auto& planned : runs_) {
      report::sweep_run run{planned.id, planned.values, planned.seed, std::nullopt, 0.0, nullptr};
      const auto dir = run_dir(planned);
      const auto record = report::read_json(dir / "sweep_run.json");
      const bool done = finished(dir);
      if (record.is_object()) {
        run.exit_status = record.value("exit_status", 0);
        run.wall_s = record.value("wall_s", 0.0);
      } else if (done) {
        run.exit_status = 0;  // a finished run from elsewhere: its folder says it ended well
      }
      if (done) run.summary = report::read_json(dir / "metrics.json")["summary"];
      if (!run.exit_status) ++missing;
      if (run.exit_status && *run.exit_status != 0) ++failed;
      results.runs.push_back(std::move(run));
    }
    const auto written = report::write_sweep_outputs(dir_, results);
    print_comparisons(results);
    std::cout << fmt::format(
        "argus sweep: {} runs, {} failed, {} not done; wrote {}, {}, {} and {} plots\n",
        runs_.size(), failed, missing, (dir_ / "sweep.csv").string(),
        (dir_ / "paired.csv").string(), (dir_ / "sweep.html").string(), written.size() - 4);
    if (interrupted) {
      std::cerr << "argus sweep: interrupted; the same command resumes it, redoing only the "
                   "runs without a complete metrics.json\n";
      return 130;
    }
    return failed > 0 ? run_failed : ok;
  }

  // The --compare metric at each value of each parameter that varies, and each value paired by
  // seed with the first (paired.csv has every metric).
  void print_comparisons(const report::sweep_results& results) const {
    const auto names = results.metric_names();
    if (std::find(names.begin(), names.end(), args_.compare) == names.end()) {
      std::cout << fmt::format("argus sweep: no run reported {} (--compare)\n", args_.compare);
      return;
    }
    auto signed_text = [](double v) { return fmt::format("{:+.4f}", v); };
    if (std::none_of(parameters_.begin(), parameters_.end(),
                     [](const auto& p) { return p.values.size() >= 2; })) {
      // One point of the grid: its runs' mean.
      std::vector<double> sample;
      for (const auto& run : results.runs)
        if (const auto m = run.metric(args_.compare)) sample.push_back(*m);
      const auto m = report::mean_with_ci95(sample);
      std::cout << fmt::format("{}: n={} mean {:.4f}", args_.compare, m.count, m.mean);
      if (m.half_width) std::cout << fmt::format(" (95% CI {:.4f} to {:.4f})", *m.low(), *m.high());
      std::cout << '\n';
      return;
    }
    for (std::size_t k = 0; k < parameters_.size(); ++k) {
      if (parameters_[k].values.size() < 2) continue;
      std::cout << fmt::format("{} by {}, each value paired by seed with {}:\n", args_.compare,
                               parameters_[k].key, parameters_[k].values.front());
      const auto points = results.metric_points(args_.compare, k);
      const auto differences = report::paired_differences(results, args_.compare, k);
      for (std::size_t v = 0; v < points.size(); ++v) {
        const auto& m = points[v].metric;
        std::string line = fmt::format("  {:<16} n={:<4} mean {}", points[v].value, m.count,
                                       m.count > 0 ? fmt::format("{:.4f}", m.mean) : "-");
        if (v > 0) {
          const auto& d = differences[v - 1];
          if (d.difference.count == 0) {
            line += "  no pairs";
          } else {
            line += fmt::format("  difference {} over {} pairs", signed_text(d.difference.mean),
                                d.difference.count);
            if (d.difference.half_width)
              line += fmt::format(" (95% CI {} to {}, SE {:.4f})",
                                  signed_text(d.difference.mean - *d.difference.half_width),
                                  signed_text(d.difference.mean + *d.difference.half_width),
                                  *d.difference.standard_error);
            line += fmt::format(", higher {} / lower {} / equal {}, sign test p {:.3g}", d.higher,
                                d.lower, d.equal, d.sign_test_p);
          }
        }
        std::cout << line << '\n';
      }
    }
  }

  const sweep_arguments& args_;
  std::vector<report::swept_parameter> parameters_;
  std::filesystem::path dir_;
  std::vector<report::planned_run> runs_;
};

int run_sweep(const sweep_arguments& args) {
  std::vector<report::swept_parameter> parameters;
  for (const auto& text : args.set) {
    parameters.push_back(*report::parse_swept_parameter(text));
    for (std::size_t k = 0; k + 1 < parameters.size(); ++k)
      if (parameters[k].key == parameters.back().key) {
        std::cerr << fmt::format(
            "argus sweep: --set: {} given twice; list all its values in one --set, e.g. "
            "{}=a,b\n",
            parameters.back().key, parameters.back().key);
        return bad_input;
      }
  }
  if (args.duration) {
    const auto d = config::parse_duration(*args.duration);
    if (!d || d->count() <= 0.0) {
      std::cerr << fmt::format(
          "argus sweep: --duration: expected a positive duration with a unit, e.g. '2 min', got "
          "'{}'\n",
          *args.duration);
      return bad_input;
    }
  }
  if (!args.program.empty() && access(args.program.c_str(), X_OK) != 0) {
    std::cerr << fmt::format("argus sweep: --argus: {} is not an executable file\n", args.program);
    return bad_input;
  }
  // Every grid point is validated before any run starts: a bad key or value is one message,
  // not a folder of failed runs.
  std::string scenario_name;
  try {
    for (const auto& run : report::plan_runs(parameters, 1)) {
      const auto scenario = config::load_scenario(args.scenario, overrides_of(parameters, run));
      // A strategy plug-in that does not load is refused here, once, as a bad value is.
      controller::resolve_strategy(scenario);
      scenario_name = scenario.name;
    }
  } catch (const config::scenario_error& e) {
    std::cerr << e.what() << '\n';
    return bad_input;
  }
  const auto dir = args.out ? std::filesystem::path(*args.out)
                            : std::filesystem::path("out") / ("sweep_" + scenario_name);
  try {
    if (args.fresh) {
      std::filesystem::remove_all(dir / "runs");
      std::filesystem::remove(dir / made_with_file);
    }
    std::filesystem::create_directories(dir / "runs");
    // What a run does besides its scenario and --set values: a run folder's name holds those.
    const nlohmann::json settings{
        {"duration", args.duration ? nlohmann::json(*args.duration) : nlohmann::json(nullptr)},
        {"feeds", args.feeds}};
    const auto made =
        made_with(args.program.empty() ? this_executable() : args.program,
                  config::to_yaml(config::load_scenario(args.scenario, {})), settings);
    if (const auto refused =
            check_resume(dir, made, !std::filesystem::is_empty(dir / "runs"), "argus sweep")) {
      std::cerr << *refused << '\n';
      return bad_input;
    }
    return sweep(args, parameters, dir).execute();
  } catch (const std::exception& e) {
    std::cerr << "argus sweep: " << e.what() << '\n';
    return run_failed;
  }
}

CLI::Validator swept_parameter_text() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        if (report::parse_swept_parameter(text)) return {};
        return fmt::format(
            "expected KEY=V1,V2,... with KEY a dotted scenario path, e.g. "
            "network.loss_probability=0,0.1,0.2, got '{}'",
            text);
      },
      "KEY=V1,V2,...");
}

}  // namespace

void add_sweep_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "sweep", "Run a scenario over a grid of --set values and seeds, in parallel processes");
  auto args = std::make_shared<sweep_arguments>();
  cmd->add_option("SCENARIO", args->scenario, "Scenario YAML file")->required();
  cmd->add_option("--seeds", args->seeds,
                  "Seeds per grid point: --first-seed to --first-seed + N - 1 (default 1)")
      ->check(integer_in(1, 100000));
  cmd->add_option("--first-seed", args->first_seed,
                  "The first seed (default 1): e.g. 1001 with --seeds 40 reports on seeds "
                  "1001-1040, apart from those settings were chosen on")
      ->check(integer_in(1, 1000000000));
  cmd->add_option("--set", args->set,
                  "A field and its values, e.g. network.loss_probability=0,0.1,0.2 (repeatable: "
                  "the grid is every combination)")
      ->check(swept_parameter_text())
      ->allow_extra_args(false);
  cmd->add_option("--jobs", args->jobs, "Runs at once (default: one per core)")
      ->check(integer_in(1, static_cast<std::int64_t>(max_jobs)));
  cmd->add_option("--threads", args->threads, "CAF threads of each run (default 1)")
      ->check(integer_in(0, 256));
  cmd->add_option("--out", args->out, "Sweep folder (default out/sweep_<scenario name>)");
  cmd->add_option("--duration", args->duration, "Virtual duration of each run, e.g. '2 min'");
  cmd->add_option("--compare", args->compare,
                  "The metric printed at the end, each value paired by seed with its parameter's "
                  "first (default mean_coverage; paired.csv has every metric)");
  cmd->add_option("--equal-within", args->equal_within,
                  "Paired differences within this of 0 count as neither higher nor lower "
                  "(default 0)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--feeds", args->feeds,
                "Let each run draw its feeds/ (key frames; runs get --no-feeds by default)");
  cmd->add_flag("--fresh", args->fresh,
                "Remove the folder's earlier runs first (a sweep resumes by default, and refuses "
                "a folder whose runs another argus executable, scenario or --duration made)");
  cmd->add_option("--argus", args->program,
                  "The argus executable the runs use (default: this one)");
  cmd->callback([args, &result] { result = run_sweep(*args); });
}

}  // namespace argus::apps
