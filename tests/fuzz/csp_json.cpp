// Fuzzes the conflict files of `argus csp solve` (apps::parse_csp), then solves what parses.
//
// A text parses or is refused with apps::csp_file_error; any other exception escapes and the
// fuzzer reports it. A conflict of at most 12 cameras and 3 groups (the search is exponential
// in both) is then solved by every solver, whose answers must be sound: each camera in at most
// one group and relevant to it, each group within its (relaxed) minimum and its maximum, the
// weight the sum of the assigned relevances; and the exact solvers, when complete, agree on the
// optimum.

#include <cmath>
#include <string>
#include <vector>

#include "apps/csp_file.hpp"
#include "protocol/csp.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

using namespace argus::protocol;

constexpr std::size_t max_cameras = 12;
constexpr std::size_t max_groups = 3;

void check_sound(const csp_problem& problem, const csp_solution& s) {
  ARGUS_FUZZ_CHECK(s.solved);
  ARGUS_FUZZ_CHECK(s.assignment.size() == problem.groups.size());
  ARGUS_FUZZ_CHECK(s.minima.size() == problem.groups.size());
  std::vector<bool> used(problem.camera_count, false);
  double weight = 0.0;
  for (std::size_t g = 0; g < problem.groups.size(); ++g) {
    const auto& group = problem.groups[g];
    const auto& cameras = s.assignment[g];
    ARGUS_FUZZ_CHECK(s.minima[g] <= group.min_cameras);
    ARGUS_FUZZ_CHECK(cameras.size() >= s.minima[g] && cameras.size() <= group.max_cameras);
    for (std::size_t k = 0; k < cameras.size(); ++k) {
      const auto c = cameras[k];
      ARGUS_FUZZ_CHECK(c < problem.camera_count);
      ARGUS_FUZZ_CHECK(k == 0 || cameras[k - 1] < c);
      ARGUS_FUZZ_CHECK(!used[c]);
      used[c] = true;
      ARGUS_FUZZ_CHECK(c < group.relevance.size() && group.relevance[c] >= problem.threshold);
      weight += group.relevance[c];
    }
  }
  ARGUS_FUZZ_CHECK(std::abs(weight - s.weight) <= 1e-9 * (1.0 + std::abs(weight)));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  argus::apps::named_csp named;
  try {
    named = argus::apps::parse_csp(std::string(argus::fuzz::text_of(data, size)), "fuzz.json");
  } catch (const argus::apps::csp_file_error&) {
    return 0;
  }
  const auto& problem = named.problem;
  ARGUS_FUZZ_CHECK(named.group_ids.size() == problem.groups.size());
  ARGUS_FUZZ_CHECK(named.camera_ids.size() == problem.camera_count);
  if (problem.camera_count > max_cameras || problem.groups.size() > max_groups) return 0;
  double optimum = std::nan("");
  for (const auto solver : {csp_solver_kind::all_solv, csp_solver_kind::best_solv,
                            csp_solver_kind::optimistic_solv, csp_solver_kind::bound_solv}) {
    const auto solution = solve(problem, solver);
    check_sound(problem, solution);
    if (!is_exact(solver) || !solution.complete) continue;
    ARGUS_FUZZ_CHECK(solution.proven_optimal);
    if (std::isnan(optimum))
      optimum = solution.weight;
    else
      ARGUS_FUZZ_CHECK(std::abs(solution.weight - optimum) <= 1e-9 * (1.0 + optimum));
  }
  return 0;
}
