// Centralising a conflict: what each leader reported becomes the solver's CSP, leaders
// included; pinned cameras and leaders that lost their target stay where they are; the answer
// maps back to camera ids and to each group's leader.

#include "controller/csp_problem_builder.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace argus::controller {
namespace {

protocol::csp_data group(protocol::task_id task, int leader, std::uint16_t min, std::uint16_t max,
                         std::vector<protocol::camera_relevance> candidates,
                         std::vector<int> pinned = {}) {
  protocol::csp_data d;
  d.task.task = task;
  d.leader = leader;
  d.term = 5;
  d.task.min_cameras = min;
  d.task.max_cameras = max;
  d.candidates = std::move(candidates);
  d.pinned = std::move(pinned);
  return d;
}

// Fig. 14: task 1 wants two cameras and sees pedestrian 1 in cameras 1 and 3; task 2 wants one
// and sees pedestrian 2 in all three. Leaders 10 and 20 stand beside them, each seeing only its
// own target: they are values of their own groups, and stay leaders.
TEST(csp_problem_builder, fig_14_is_solved_as_the_paper_answers) {
  auto built = build_csp({group(2, 20, 2, 2, {{20, 0.5}, {1, 0.6}, {2, 0.9}, {3, 0.6}}),
                          group(1, 10, 3, 3, {{10, 0.5}, {1, 0.8}, {3, 0.7}})},
                         0.1);
  ASSERT_EQ(built.groups.size(), 2u);
  EXPECT_EQ(built.groups[0].task.task, 1u);  // task order
  EXPECT_EQ(built.cameras, (std::vector<int>{1, 2, 3, 10, 20}));
  EXPECT_EQ(built.problem.groups[0].min_cameras, 3u);
  EXPECT_TRUE(std::isnan(built.problem.groups[0].relevance[1]));
  const auto solution = protocol::solve(built.problem, protocol::csp_solver_kind::all_solv);
  EXPECT_EQ(built.assigned(solution, 0), (std::vector<int>{1, 3, 10}));
  EXPECT_EQ(built.assigned(solution, 1), (std::vector<int>{2, 20}));
  const auto plan = built.plan(solution);
  EXPECT_EQ(plan[0].leader, 10);
  EXPECT_EQ(plan[0].term, 5u);  // the same leadership
  EXPECT_EQ(plan[1].leader, 20);
  EXPECT_FALSE(solution.relaxed);
}

// Fig. 19: camera 1 leads the green top's task, camera 2 the first pedestrian's; each also
// sees the other's target, and the CSP swaps them when that is worth more.
TEST(csp_problem_builder, leaders_are_values_and_a_moved_leader_is_replaced) {
  auto built = build_csp(
      {group(0, 2, 1, 2, {{2, 0.3}, {1, 0.8}}), group(1, 1, 1, 1, {{1, 0.4}, {2, 0.7}})}, 0.1);
  EXPECT_EQ(built.cameras, (std::vector<int>{1, 2}));
  const auto solution = protocol::solve(built.problem, protocol::csp_solver_kind::all_solv);
  const auto plan = built.plan(solution);
  ASSERT_EQ(plan.size(), 2u);
  EXPECT_EQ(plan[0].leader, 1);  // 0.8 + 0.7 beats 0.3 + 0.4
  EXPECT_EQ(plan[0].term, 6u);   // a new leadership, a new epoch
  EXPECT_EQ(plan[0].previous, 2);
  EXPECT_DOUBLE_EQ(plan[0].relevance, 0.8);
  EXPECT_TRUE(plan[0].members.empty());
  EXPECT_EQ(plan[1].leader, 2);
  EXPECT_EQ(plan[1].previous, 1);
}

TEST(csp_problem_builder, pinned_cameras_and_blind_leaders_never_move) {
  // Group 1's leader 10 is pinned, camera 1 too; group 2's leader 20 no longer sees its target.
  auto built = build_csp({group(1, 10, 2, 3, {{10, 0.9}, {1, 0.2}, {2, 0.3}}, {1, 10}),
                          group(2, 20, 1, 2, {{20, 0.05}, {1, 0.9}, {2, 0.8}, {10, 0.9}})},
                         0.1);
  EXPECT_EQ(built.cameras, std::vector<int>{2});
  EXPECT_EQ(built.fixed[0], (std::vector<int>{1, 10}));
  EXPECT_EQ(built.fixed[1], (std::vector<int>{20}));
  EXPECT_EQ(built.problem.groups[0].max_cameras, 1u);
  EXPECT_EQ(built.problem.groups[1].min_cameras, 0u);
  const auto solution = protocol::solve(built.problem, protocol::csp_solver_kind::all_solv);
  EXPECT_EQ(built.assigned(solution, 0), (std::vector<int>{1, 10}));
  EXPECT_EQ(built.assigned(solution, 1), (std::vector<int>{2, 20}));
  EXPECT_EQ(built.plan(solution)[1].leader, 20);
}

TEST(csp_problem_builder, a_group_left_with_no_camera_keeps_its_leader) {
  // Both leaders see only task 0's target well; task 1 may go to 0 cameras only by a
  // relaxation, which the plan undoes: a conflict never ends a task.
  built_csp built;
  built.groups = {{.task = {}, .leader = 1, .term = 3}, {.task = {}, .leader = 2, .term = 4}};
  built.groups[1].task.task = 1;
  built.cameras = {1, 2};
  built.fixed = {{}, {}};
  built.reported = {{{1, 0.9}, {2, 0.8}}, {{2, 0.05}}};
  protocol::csp_solution solution;
  solution.solved = true;
  solution.assignment = {{0, 1}, {}};
  const auto plan = built.plan(solution);
  EXPECT_EQ(plan[0].leader, 1);
  ASSERT_EQ(plan[0].members.size(), 0u);
  EXPECT_EQ(plan[1].leader, 2);
  EXPECT_EQ(plan[1].term, 4u);
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
