#pragma once

// Checking a conflict's answer from the log alone: a csp_solved line states the CSP it solved
// (tasks, movable cameras, minima and maxima, relevances, the cameras that stay) and its answer
// (each group's leader and other cameras). The answer must be the optimum of that problem, as
// AllSolv, which enumerates every solution, finds it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "nlohmann/json.hpp"
#include "protocol/csp.hpp"

namespace argus::testing {

/// The CSP a csp_solved line states, and its answer: each group's cameras, its leader first.
struct logged_csp {
  protocol::csp_problem problem;
  std::vector<int> camera_ids;
  std::vector<std::vector<int>> fixed;
  std::vector<std::vector<int>> answer;
  double weight = 0.0;
};

/// `line`: the csp_solved event as a JSON object.
inline logged_csp read_csp(const nlohmann::json& line, double threshold = 0.1) {
  logged_csp out;
  out.camera_ids = line.at("camera_ids").get<std::vector<int>>();
  out.fixed = line.at("fixed").get<std::vector<std::vector<int>>>();
  out.weight = line.at("weight").get<double>();
  out.problem.camera_count = out.camera_ids.size();
  out.problem.threshold = threshold;
  for (std::size_t g = 0; g < line.at("tasks").size(); ++g) {
    protocol::csp_group group;
    group.min_cameras = line.at("min_cameras")[g].get<unsigned>();
    group.max_cameras = line.at("max_cameras")[g].get<unsigned>();
    for (double r : line.at("relevance")[g].get<std::vector<double>>())
      group.relevance.push_back(r < 0.0 ? std::nan("") : r);
    out.problem.groups.push_back(group);
    std::vector<int> cameras{line.at("leaders")[g].get<int>()};
    for (int c : line.at("assigned")[g].get<std::vector<int>>()) cameras.push_back(c);
    out.answer.push_back(cameras);
  }
  return out;
}

/// Expects the answer `line` states to be the optimum of the problem it states (its weight, to
/// the log's four decimals, and its cameras, when the optimum is unique in weight).
inline void expect_optimal(const nlohmann::json& line, double threshold = 0.1) {
  SCOPED_TRACE(line.dump());
  const auto logged = read_csp(line, threshold);
  const auto best = protocol::solve(logged.problem, protocol::csp_solver_kind::all_solv);
  ASSERT_TRUE(best.solved);
  EXPECT_NEAR(logged.weight, best.weight, 1e-4);
  EXPECT_TRUE(line.at("optimal").get<bool>());
  for (std::size_t g = 0; g < logged.answer.size(); ++g) {
    std::vector<int> optimum = logged.fixed[g];
    for (auto i : best.assignment[g]) optimum.push_back(logged.camera_ids[i]);
    auto answer = logged.answer[g];
    std::sort(optimum.begin(), optimum.end());
    std::sort(answer.begin(), answer.end());
    EXPECT_EQ(answer, optimum) << "group " << g;
  }
}

}  // namespace argus::testing
