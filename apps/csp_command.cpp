// `argus csp`: group-group conflict resolution (Section IV-B). `solve` settles one conflict
// read from a JSON file (apps/csp_file.hpp) within a budget; `table1` regenerates Table 1's
// experiment (protocol/csp_table1.hpp) with every solver.

#include <algorithm>
#include <charconv>
#include <chrono>
#include <iostream>
#include <optional>

#include "apps/commands.hpp"
#include "apps/csp_file.hpp"
#include "config/derive_seed.hpp"
#include "fmt/format.h"
#include "nlohmann/json.hpp"
#include "protocol/csp.hpp"
#include "protocol/csp_table1.hpp"

namespace argus::apps {
namespace {

using ordered_json = nlohmann::ordered_json;
using protocol::csp_solver_kind;

struct solver_name {
  csp_solver_kind kind;
  const char* option;  // as --solver and the output spell it
  const char* paper;   // as Table 1 spells it
};
constexpr solver_name solver_names[] = {
    {csp_solver_kind::all_solv, "allsolv", "AllSolv"},
    {csp_solver_kind::best_solv, "bestsolv", "BestSolv"},
    {csp_solver_kind::optimistic_solv, "optimisticsolv", "OptimisticSolv"},
    {csp_solver_kind::bound_solv, "boundsolv", "BoundSolv"}};
constexpr std::size_t solver_count = std::size(solver_names);

/// The largest conflict `argus csp solve` accepts: far beyond any a run builds (a conflict
/// gathers the groups that bid for one busy camera and their neighbours' cameras), and small
/// enough that building the problem and the greedy answer stay instant.
constexpr std::size_t max_groups = 64;
constexpr std::size_t max_cameras = 4096;

std::optional<std::uint64_t> whole_number(const std::string& text) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// ---- argus csp solve ------------------------------------------------------------------------

struct solve_arguments {
  std::string file;
  std::string solver = "optimisticsolv";
  double max_seconds = 10.0;
  std::uint64_t max_work = 0;
  std::size_t max_memory_mb = 256;
};

int solve_file(const solve_arguments& args) {
  const auto solver = std::find_if(std::begin(solver_names), std::end(solver_names),
                                   [&](const solver_name& s) { return args.solver == s.option; });
  if (solver == std::end(solver_names)) {
    std::cerr << fmt::format(
        "argus csp solve: --solver: expected one of allsolv, bestsolv, optimisticsolv, "
        "boundsolv, got '{}'\n",
        args.solver);
    return bad_input;
  }
  named_csp named;
  try {
    named = read_csp_file(args.file);
  } catch (const csp_file_error& e) {
    std::cerr << e.what() << '\n';
    return bad_input;
  }
  if (named.problem.groups.size() > max_groups || named.problem.camera_count > max_cameras) {
    std::cerr << fmt::format(
        "argus csp solve: {}: {} groups and {} cameras; the largest conflict accepted has {} "
        "groups and {} cameras\n",
        args.file, named.problem.groups.size(), named.problem.camera_count, max_groups,
        max_cameras);
    return bad_input;
  }
  const protocol::csp_limits limits{.max_work = args.max_work,
                                    .max_seconds = args.max_seconds,
                                    .max_memory_bytes = args.max_memory_mb << 20};
  const auto start = std::chrono::steady_clock::now();
  const auto solution = protocol::solve(named.problem, solver->kind, limits);
  const double time_ms = milliseconds_since(start);
  if (!solution.solved) {  // cannot happen: every minimum can go down to 0 (csp.hpp)
    std::cerr << "argus csp solve: " << args.file << ": no assignment\n";
    return run_failed;
  }
  ordered_json assignment = ordered_json::object();
  ordered_json minima = ordered_json::object();
  for (std::size_t g = 0; g < named.group_ids.size(); ++g) {
    auto cameras = ordered_json::array();
    for (std::size_t c : solution.assignment[g]) cameras.push_back(named.camera_ids[c]);
    assignment[named.group_ids[g]] = cameras;
    minima[named.group_ids[g]] = solution.minima[g];
  }
  ordered_json out;
  out["assignment"] = assignment;
  out["weight"] = solution.weight;
  out["minima"] = minima;
  out["relaxed"] = solution.relaxed;
  out["nodes_explored"] = solution.nodes_explored;
  out["backtracks"] = solution.backtracks;
  out["complete"] = solution.complete;
  out["proven_optimal"] = solution.proven_optimal;
  out["stopped_by"] = solution.stopped_by == protocol::csp_stop::none
                          ? ordered_json(nullptr)
                          : ordered_json(protocol::stop_name(solution.stopped_by));
  out["solver"] = solver->option;
  out["time_ms"] = time_ms;
  std::cout << out.dump() << '\n';
  return ok;
}

// ---- argus csp table1 -----------------------------------------------------------------------

struct table1_arguments {
  std::string seed = "1";
  std::string instances = "100";
  bool json = false;
};

/// One solver's totals over the instances of one setting.
struct solver_totals {
  double solutions = 0, nodes = 0, backtracks = 0, time_ms = 0, max_time_ms = 0;
  std::uint64_t missed = 0;  // instances whose answer is lighter than the optimum
  double shortfall = 0;      // summed relative shortfall on those
};

/// The paper's figures for one solver in one setting.
struct paper_counts {
  double solutions, nodes, backtracks;
};

/// One setting of Table 1 with the paper's figures for it.
struct table1_row {
  const char* cases;
  protocol::table1_setting setting;
  double paper_domain;
  paper_counts paper[2];  // AllSolv, BestSolv
};
constexpr table1_row table1_rows[] = {
    {"1-2", protocol::table1_cases_1_2, 220, {{29290, 29511, 48620}, {9, 175, 36520}}},
    {"3-4", protocol::table1_cases_3_4, 560, {{221347, 221908, 314160}, {17, 401, 215040}}}};

double domain_size(const protocol::csp_problem& problem, std::size_t g) {
  std::size_t relevant = 0;
  for (double r : problem.groups[g].relevance) relevant += r >= problem.threshold;
  double size = 0.0, binomial = 1.0;  // C(relevant, s)
  for (std::size_t s = 0; s <= std::min<std::size_t>(relevant, problem.groups[g].max_cameras);
       ++s) {
    if (s >= problem.groups[g].min_cameras) size += binomial;
    binomial = binomial * static_cast<double>(relevant - s) / static_cast<double>(s + 1);
  }
  return size;
}

int table1(const table1_arguments& args) {
  const auto seed = whole_number(args.seed);
  if (!seed) {
    std::cerr << fmt::format(
        "argus csp table1: --seed: expected a non-negative integer, got '{}'\n", args.seed);
    return bad_input;
  }
  const auto instances = whole_number(args.instances);
  if (!instances || *instances == 0) {
    std::cerr << fmt::format(
        "argus csp table1: --instances: expected a positive integer, got '{}'\n", args.instances);
    return bad_input;
  }
  ordered_json settings = ordered_json::array();
  if (!args.json)
    std::cout << fmt::format(
        "Table 1: 2 groups, 3 sensors each; {} random instances per setting, seed {}\n"
        "{:>5} {:>8} {:<14} {:>7} {:>11} {:>11} {:>11} {:>9} {:>9} {:>8} {:>7} "
        "{:>15} {:>7} {:>8}\n",
        *instances, *seed, "cases", "relevant", "solver", "domain", "solutions", "nodes",
        "backtracks", "mean ms", "max ms", "missed", "short", "paper solutions", "nodes",
        "backtr.");
  for (const auto& row : table1_rows) {
    solver_totals totals[solver_count];
    double domain = 0.0;
    for (std::uint64_t i = 0; i < *instances; ++i) {
      const auto problem =
          protocol::make_table1_instance(row.setting, config::derive_seed(*seed, i));
      domain += (domain_size(problem, 0) + domain_size(problem, 1)) / 2.0;
      std::optional<protocol::csp_solution> reference;  // AllSolv's, the optimum
      for (std::size_t s = 0; s < solver_count; ++s) {
        const auto start = std::chrono::steady_clock::now();
        auto solution = protocol::solve(problem, solver_names[s].kind);
        const double time_ms = milliseconds_since(start);
        auto& t = totals[s];
        t.solutions += static_cast<double>(solution.solutions);
        t.nodes += static_cast<double>(solution.nodes_explored);
        t.backtracks += static_cast<double>(solution.backtracks);
        t.time_ms += time_ms;
        t.max_time_ms = std::max(t.max_time_ms, time_ms);
        if (!reference) {
          reference = std::move(solution);
          continue;
        }
        if (solution.assignment == reference->assignment && solution.weight == reference->weight)
          continue;
        if (protocol::is_exact(solver_names[s].kind)) {
          std::cerr << fmt::format(
              "argus csp table1: {} and AllSolv disagree on instance {} of cases {}\n",
              solver_names[s].paper, i, row.cases);
          return run_failed;
        }
        ++t.missed;  // the paper's BestSolv can miss the optimum (protocol/csp.hpp)
        t.shortfall += (reference->weight - solution.weight) / reference->weight;
      }
    }
    const double n = static_cast<double>(*instances);
    ordered_json solvers = ordered_json::array();
    for (std::size_t s = 0; s < solver_count; ++s) {
      const auto& t = totals[s];
      const paper_counts* paper = s < 2 ? &row.paper[s] : nullptr;  // AllSolv and BestSolv
      const double shortfall = t.missed ? t.shortfall / static_cast<double>(t.missed) : 0.0;
      if (args.json) {
        ordered_json entry;
        entry["solver"] = solver_names[s].option;
        entry["exact"] = protocol::is_exact(solver_names[s].kind);
        entry["solutions"] = t.solutions / n;
        entry["nodes_explored"] = t.nodes / n;
        entry["backtracks"] = t.backtracks / n;
        entry["mean_ms"] = t.time_ms / n;
        entry["max_ms"] = t.max_time_ms;
        entry["missed_optimum"] = t.missed;
        entry["mean_shortfall_when_missed"] = shortfall;
        entry["paper_solutions"] = paper ? ordered_json(paper->solutions) : ordered_json(nullptr);
        entry["paper_nodes_explored"] = paper ? ordered_json(paper->nodes) : ordered_json(nullptr);
        entry["paper_backtracks"] = paper ? ordered_json(paper->backtracks) : ordered_json(nullptr);
        solvers.push_back(entry);
      } else {
        const auto figure = [&](double value) {
          return paper ? fmt::format("{:.0f}", value) : std::string("-");
        };
        std::cout << fmt::format(
            "{:>5} {:>8} {:<14} {:>7.0f} {:>11.1f} {:>11.1f} {:>11.1f} {:>9.4f} {:>9.4f} "
            "{:>8} {:>6.2f}% {:>15} {:>7} {:>8}\n",
            row.cases, row.setting.relevant_per_group, solver_names[s].paper, domain / n,
            t.solutions / n, t.nodes / n, t.backtracks / n, t.time_ms / n, t.max_time_ms, t.missed,
            100.0 * shortfall, figure(paper ? paper->solutions : 0),
            figure(paper ? paper->nodes : 0), figure(paper ? paper->backtracks : 0));
      }
    }
    if (args.json) {
      ordered_json setting;
      setting["cases"] = row.cases;
      setting["relevant_per_group"] = row.setting.relevant_per_group;
      setting["shared"] = row.setting.shared;
      setting["domain_size"] = domain / n;
      setting["paper_domain_size"] = row.paper_domain;
      setting["solvers"] = solvers;
      settings.push_back(setting);
    }
  }
  if (args.json) {
    ordered_json out;
    out["seed"] = *seed;
    out["instances"] = *instances;
    out["exact_solvers_agree"] = true;
    out["settings"] = settings;
    std::cout << out.dump() << '\n';
  } else {
    std::cout << "The exact solvers (AllSolv, OptimisticSolv, BoundSolv) returned the same "
                 "assignment on every instance; \"missed\" counts the instances where the\n"
                 "paper's BestSolv rule returned a lighter one, \"short\" by how much of the "
                 "optimum's weight on average.\n";
  }
  return ok;
}

}  // namespace

void add_csp_command(CLI::App& app, int& result) {
  auto* csp = app.add_subcommand(
      "csp", "Group-group conflict resolution as a CSP (paper Section IV-B, Table 1)");
  csp->require_subcommand(1);

  auto* solve = csp->add_subcommand(
      "solve",
      "Assign cameras to conflicting groups read from a JSON file (up to 64 groups and 4096 "
      "cameras) within a budget; prints one JSON line");
  auto solve_args = std::make_shared<solve_arguments>();
  solve
      ->add_option("FILE", solve_args->file,
                   "JSON file: {\"groups\": [{\"id\", \"min_cameras\", \"max_cameras\", "
                   "\"relevance\": {camera: r}}], \"threshold\"}")
      ->required();
  solve->add_option("--solver", solve_args->solver,
                    "optimisticsolv (default) | bestsolv (the paper's rule, not always optimal) "
                    "| allsolv | boundsolv");
  solve
      ->add_option("--max-seconds", solve_args->max_seconds,
                   "Wall-clock budget; past it the best assignment found so far is printed "
                   "with \"proven_optimal\": false (default 10; 0: none)")
      ->check(CLI::NonNegativeNumber);
  solve->add_option("--max-work", solve_args->max_work,
                    "Budget in values tried, the same on every machine (default 0: none)");
  solve
      ->add_option("--max-memory-mb", solve_args->max_memory_mb,
                   "Memory the search may hold, in MiB (default 256)")
      ->check(CLI::PositiveNumber);
  solve->callback([solve_args, &result] { result = solve_file(*solve_args); });

  auto* table = csp->add_subcommand(
      "table1",
      "Regenerate Table 1 (2 groups x 3 sensors, 12 and 16 relevant) with every solver, beside "
      "the paper's counts");
  auto table_args = std::make_shared<table1_arguments>();
  table->add_option("--seed", table_args->seed, "Seed of the random instances (default 1)");
  table->add_option("--instances", table_args->instances,
                    "Random instances per setting (default 100)");
  table->add_flag("--json", table_args->json, "Print the table as one JSON object");
  table->callback([table_args, &result] { result = table1(*table_args); });
}

}  // namespace argus::apps
