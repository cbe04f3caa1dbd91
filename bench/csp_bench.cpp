// CSP conflict resolution (Section IV-B, Table 1): time per instance of AllSolv, BestSolv (the
// paper's rule), optimistic_solv and bound_solv on Table 1's two settings (protocol/csp_table1.hpp:
// 2 groups x 3 sensors, 12 or 16 relevant sensors each), cycling over 100 seeded instances.
// Counters: nodes explored and backtracks per instance. Targets (issue 14): BestSolv at most 2% of
// AllSolv's nodes, bound_solv at least 10x fewer than BestSolv, each under 1 ms per instance.
// `argus csp table1` prints the same experiment as a table with the paper's figures.
#include <benchmark/benchmark.h>

#include <vector>

#include "config/derive_seed.hpp"
#include "protocol/csp.hpp"
#include "protocol/csp_table1.hpp"

namespace {

using namespace argus::protocol;

constexpr int instance_count = 100;

/// The seeded instances of one setting, as `argus csp table1 --seed 1` draws them.
const std::vector<csp_problem>& instances(int relevant_per_group) {
  static const auto make = [](const table1_setting& setting) {
    std::vector<csp_problem> out;
    for (int i = 0; i < instance_count; ++i)
      out.push_back(make_table1_instance(setting, argus::config::derive_seed(1, i)));
    return out;
  };
  static const auto small = make(table1_cases_1_2);
  static const auto large = make(table1_cases_3_4);
  return relevant_per_group == 12 ? small : large;
}

void table1_solve(benchmark::State& state) {
  const auto& problems = instances(static_cast<int>(state.range(0)));
  const auto solver = static_cast<csp_solver_kind>(state.range(1));
  std::size_t next = 0;
  double nodes = 0.0, backtracks = 0.0;
  for (auto _ : state) {
    const auto solution = solve(problems[next], solver);
    benchmark::DoNotOptimize(solution.weight);
    nodes += static_cast<double>(solution.nodes_explored);
    backtracks += static_cast<double>(solution.backtracks);
    next = (next + 1) % problems.size();
  }
  state.counters["nodes"] = benchmark::Counter(nodes, benchmark::Counter::kAvgIterations);
  state.counters["backtracks"] = benchmark::Counter(backtracks, benchmark::Counter::kAvgIterations);
}

// Args: relevant sensors per group, solver (csp_solver_kind: 0 AllSolv, 1 BestSolv,
// 2 optimistic_solv, 3 bound_solv).
BENCHMARK(table1_solve)
    ->ArgNames({"relevant", "solver"})
    ->ArgsProduct({{12, 16}, {0, 1, 2, 3}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
