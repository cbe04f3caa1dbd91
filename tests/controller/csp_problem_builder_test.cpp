// Centralising a conflict: what each leader reported becomes the solver's CSP, leaders and
// pinned members stay where they are, and the answer maps back to camera ids.

#include "controller/csp_problem_builder.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace argus::controller {
namespace {

protocol::csp_data group(protocol::task_id task, int leader, std::uint16_t min, std::uint16_t max,
                         std::vector<protocol::camera_relevance> candidates,
                         std::vector<int> pinned = {}) {
  protocol::csp_data d;
  d.task = task;
  d.leader = leader;
  d.min_cameras = min;
  d.max_cameras = max;
  d.candidates = std::move(candidates);
  d.pinned = std::move(pinned);
  return d;
}

// Fig. 14: task 1 wants two cameras and sees pedestrian 1 in cameras 1 and 3; task 2 wants one
// and sees pedestrian 2 in all three. Leaders 10 and 20 stand beside them.
TEST(csp_problem_builder, fig_14_is_solved_as_the_paper_answers) {
  auto built = build_csp({group(2, 20, 2, 2, {{1, 0.6}, {2, 0.9}, {3, 0.6}}),
                          group(1, 10, 3, 3, {{1, 0.8}, {3, 0.7}})},
                         0.1);
  ASSERT_EQ(built.groups.size(), 2u);
  EXPECT_EQ(built.groups[0].task, 1u);  // task order
  EXPECT_EQ(built.cameras, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(built.problem.groups[0].min_cameras, 2u);  // the leader is one of the three
  EXPECT_TRUE(std::isnan(built.problem.groups[0].relevance[1]));
  const auto solution = protocol::solve(built.problem, protocol::csp_solver_kind::best_solv);
  EXPECT_EQ(built.assigned(solution, 0), (std::vector<int>{1, 3}));
  EXPECT_EQ(built.assigned(solution, 1), (std::vector<int>{2}));
  EXPECT_FALSE(solution.relaxed);
}

TEST(csp_problem_builder, pinned_members_and_leaders_never_move) {
  auto built = build_csp({group(1, 10, 2, 3, {{1, 0.2}, {2, 0.3}}, {1}),
                          group(2, 20, 1, 2, {{1, 0.9}, {2, 0.8}, {10, 0.9}})},
                         0.1);
  EXPECT_EQ(built.cameras, std::vector<int>{2});
  EXPECT_EQ(built.problem.groups[0].max_cameras, 1u);
  const auto solution = protocol::solve(built.problem, protocol::csp_solver_kind::all_solv);
  EXPECT_EQ(built.assigned(solution, 0), (std::vector<int>{1}));
  EXPECT_EQ(built.assigned(solution, 1), (std::vector<int>{2}));
}

TEST(csp_problem_builder, each_solver_the_scenario_names) {
  EXPECT_EQ(solver_kind(config::conflict_solver::all_solv), protocol::csp_solver_kind::all_solv);
  EXPECT_EQ(solver_kind(config::conflict_solver::best_solv), protocol::csp_solver_kind::best_solv);
  EXPECT_EQ(solver_kind(config::conflict_solver::optimistic_solv),
            protocol::csp_solver_kind::optimistic_solv);
  EXPECT_EQ(solver_kind(config::conflict_solver::bound_solv),
            protocol::csp_solver_kind::bound_solv);
}

}  // namespace
}  // namespace argus::controller
