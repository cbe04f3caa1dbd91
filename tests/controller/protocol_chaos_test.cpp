// The protocol under random loss, duplicates, link cuts and crashes, over 200 seeds each for both
// merge rules, checked every tick against its invariants (docs/protocol.md, "Terms"):
//  - safety, always: a node's epoch in a task never goes back while it stays in the task, and
//    no member is ahead of the leader it follows (a live leader of its task);
//  - after the faults stop: no task has two leaders for longer than the merge timeout
//    (hand-overs and stale status under delay may make two for a while; the merge must end it),
//    no task held by live nodes is without a leader, and no member follows a node that is not a
//    live leader of its task, each for longer than the leader failure timeout allows.

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>

#include "tests/controller/protocol_harness.hpp"
#include "world/rng.hpp"

namespace argus::controller {
namespace {

using testing::centred_box;
using testing::protocol_harness;
using testing::test_scenario;
using testing::test_task;

struct chaos_outcome {
  std::int64_t longest_two_leaders_after_faults = 0;
  std::int64_t longest_leaderless_after_faults = 0;
  std::int64_t longest_orphan_after_faults = 0;
  std::size_t epochs_gone_back = 0;
  std::size_t members_ahead = 0;
  std::size_t csp_solved = 0;
  std::size_t handoffs = 0;
};

chaos_outcome run_chaos(std::uint64_t seed, config::merge_rule rule) {
  auto s = test_scenario({1, 2, 3, 4, 5});
  s.controller.merge = rule;
  s.controller.merge_timeout = config::seconds{10.0};
  s.controller.min_task_duration = config::seconds{0.0};
  protocol_harness h(std::move(s), 2 + static_cast<std::int64_t>(seed % 3));
  auto random = std::make_shared<world::rng>(seed);
  h.sees = [random](int camera, task_id task, std::int64_t tick) -> std::optional<cv::Rect2d> {
    // Each camera sees each target in its own stretch of time, as if the target walked by.
    const auto phase = (tick / 150 + camera + static_cast<std::int64_t>(task)) % 5;
    if (phase > 2) return std::nullopt;
    return centred_box();
  };
  // A cut between two cameras for a while, during the auctions and conflicts.
  world::rng cut(seed * 104729 + 3);
  const int cut_a = 1 + static_cast<int>(cut.below(5));
  const int cut_b = 1 + static_cast<int>(cut.below(5));
  const auto cut_from = static_cast<std::int64_t>(cut.below(300));
  auto clock = std::make_shared<std::int64_t>(0);
  h.drop = [random, cut_a, cut_b, cut_from, clock](int from, int to,
                                                   const protocol::group_message&) {
    const bool cut_now = *clock >= cut_from && *clock < cut_from + 100 &&
                         ((from == cut_a && to == cut_b) || (from == cut_b && to == cut_a));
    return cut_now || random->chance(0.1);
  };
  h.duplicate = [random](int, int, const protocol::group_message&) { return random->chance(0.05); };
  auto a = test_task(2, 3);
  auto b = test_task(1, 2);
  b.task = 8;
  h.operator_query_at(0, 1, a);
  h.operator_query_at(50, 2, b);
  // Up to two crashes before tick 400, and a second operator query for task 7 elsewhere
  // (a duplicate group that must merge).
  world::rng plan(seed * 7919 + 1);
  h.operator_query_at(100 + plan.below(200), 3 + static_cast<int>(plan.below(3)), a);
  std::vector<std::pair<std::int64_t, int>> crashes;
  for (int k = 0; k < 2; ++k)
    crashes.emplace_back(plan.below(400), 1 + static_cast<int>(plan.below(5)));
  std::sort(crashes.begin(), crashes.end());
  chaos_outcome out;
  std::map<task_id, std::int64_t> since;  // start of the current stretch of two leaders
  std::map<task_id, std::int64_t> leaderless_since;
  std::map<int, std::int64_t> orphan_since;
  std::map<int, std::pair<task_id, protocol::term_epoch>> last_term;  // per node, while in a task
  const auto stretch = [](auto& starts, auto key, bool now_bad, std::int64_t t,
                          std::int64_t& longest) {
    if (!now_bad) {
      starts.erase(key);
      return;
    }
    const auto start = starts.emplace(key, t).first->second;
    longest = std::max(longest, t - start + 1);
  };
  for (std::int64_t t = 0; t < 1200; ++t) {
    for (const auto& [at, camera] : crashes)
      if (at == t) h.crash(camera);
    *clock = t;
    h.run_until(t + 1);
    // Safety, every tick.
    for (int id : h.ids()) {
      if (h.down(id)) continue;
      auto& n = h.node(id);
      if (!n.task()) {
        last_term.erase(id);
        continue;
      }
      auto [it, fresh] = last_term.emplace(id, std::pair{*n.task(), n.term()});
      if (!fresh) {
        if (it->second.first == *n.task() && n.term() < it->second.second) ++out.epochs_gone_back;
        it->second = {*n.task(), n.term()};
      }
      if (n.role() == group_role::member && !n.handing_over() && !h.down(n.leader())) {
        auto& leader = h.node(n.leader());
        if (leader.task() == n.task() && leader.role() == group_role::leader &&
            n.term() > leader.term())
          ++out.members_ahead;
      }
    }
    if (t < 400) continue;  // faults end at 400
    for (task_id task : {7u, 8u}) {
      bool held = false;
      for (int id : h.ids()) held = held || (!h.down(id) && h.node(id).task() == task);
      auto longest = out.longest_leaderless_after_faults;
      stretch(leaderless_since, task, held && h.leaders(task).empty(), t, longest);
      out.longest_leaderless_after_faults = longest;
    }
    for (int id : h.ids()) {
      auto& n = h.node(id);
      bool orphan = false;
      if (!h.down(id) && n.task() && n.role() == group_role::member) {
        const int l = n.leader();
        orphan =
            h.down(l) || h.node(l).task() != n.task() || h.node(l).role() != group_role::leader;
      }
      auto longest = out.longest_orphan_after_faults;
      stretch(orphan_since, id, orphan, t, longest);
      out.longest_orphan_after_faults = longest;
    }
    for (task_id task : {7u, 8u}) {
      if (h.leaders(task).size() <= 1) {
        since.erase(task);
        continue;
      }
      const auto start = since.emplace(task, t).first->second;
      out.longest_two_leaders_after_faults =
          std::max(out.longest_two_leaders_after_faults, t - start + 1);
    }
  }
  out.csp_solved = h.count("csp_solved");
  out.handoffs = h.count("handoff");
  return out;
}

// `bound`: the merge timeout (100 ticks) for the id rule; twice that for Fig. 15, where a lost
// demote is only given up after the merge timeout, and the next attempt waits for a status.
void chaos(config::merge_rule rule, std::int64_t bound) {
  std::size_t solved = 0, handoffs = 0;
  std::int64_t worst_leaderless = 0, worst_orphan = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const auto r = run_chaos(seed, rule);
    EXPECT_LE(r.longest_two_leaders_after_faults, bound) << "seed " << seed;
    EXPECT_EQ(r.epochs_gone_back, 0u) << "seed " << seed;
    EXPECT_EQ(r.members_ahead, 0u) << "seed " << seed;
    if (r.longest_leaderless_after_faults > 45 || r.longest_orphan_after_faults > 45) std::cout << "DBG seed " << seed << " " << r.longest_leaderless_after_faults << " " << r.longest_orphan_after_faults << "\n";
    worst_leaderless = std::max(worst_leaderless, r.longest_leaderless_after_faults);
    worst_orphan = std::max(worst_orphan, r.longest_orphan_after_faults);
    solved += r.csp_solved;
    handoffs += r.handoffs;
  }
  // A member whose leader is gone leads itself after the leader failure timeout (3 s); a
  // status's delay (up to 0.4 s here) and a heartbeat (1 s) on top.
  std::cout << "longest leaderless stretch " << worst_leaderless << " ticks, longest orphan "
            << worst_orphan << " ticks\n";
  EXPECT_LE(worst_leaderless, 45);
  EXPECT_LE(worst_orphan, 45);
  // The runs exercise what they claim to: conflicts solved, groups handed over.
  EXPECT_GT(solved, 0u);
  EXPECT_GT(handoffs, 0u);
}

TEST(protocol_chaos, one_leader_per_task_after_faults_with_the_highest_id_rule) {
  chaos(config::merge_rule::highest_id, 100);
}

TEST(protocol_chaos, one_leader_per_task_after_faults_with_fig_15_negotiation) {
  chaos(config::merge_rule::negotiation, 200);
}

}  // namespace
}  // namespace argus::controller
