// Section IV-C end to end on real threads: a group outlives its leader's crash and keeps the
// target observed. Penn Station, emulated; about 15 s in Release. Labelled slow: the sanitizer
// builds reach the same runtime paths through surveillance_test and chaos_test.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "actors/run_scenario.hpp"
#include "config/scenario_loader.hpp"
#include "nlohmann/json.hpp"
#include "surveillance_runs.hpp"

namespace argus::actors {
namespace {

using surveillance_runs::events_of;
using surveillance_runs::station;

// The cameras leading task 0 at `t` seconds, from the log: leaders come with task_created and
// self-promotions, and go when demoted (leader_changed to another), hand over, or leave.
std::set<int> leaders_at(const std::vector<nlohmann::json>& events, double t) {
  std::set<int> leaders;
  for (const auto& e : events) {
    if (e["t"].get<double>() > t) break;
    const auto& kind = e["kind"];
    if (kind == "task_created") leaders.insert(e["camera"].get<int>());
    if (kind == "leader_changed") {
      if (e["leader"] == e["camera"])
        leaders.insert(e["camera"].get<int>());
      else
        leaders.erase(e["camera"].get<int>());
    }
    if (kind == "left_task" && e["role"] == "leader") leaders.erase(e["camera"].get<int>());
    // A leader that hands its group over follows the new leader until it hears it lead.
    if (kind == "handoff") leaders.erase(e["camera"].get<int>());
    if (kind == "fault" && e["fault"] == "crash" && e["applied"] == true)
      leaders.erase(e["camera"].get<int>());
  }
  return leaders;
}

// The one camera leading task 0 at `t`; 0 when none or several lead.
int leader_at(const std::vector<nlohmann::json>& events, double t) {
  const auto leaders = leaders_at(events, t);
  return leaders.size() == 1 ? *leaders.begin() : 0;
}

// observed), and the time of each tick.
struct member_holds {
  std::map<std::int64_t, std::set<int>> by_tick;
  std::map<std::int64_t, double> seconds;
};

member_holds members_holding_her(const std::filesystem::path& run) {
  member_holds out;
  std::ifstream in(run / "tracks.csv");
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) f.push_back(cell);
    const auto tick = std::stoll(f.at(0));
    out.seconds[tick] = std::stod(f.at(1));
    if (f.at(3) == "0" && f.at(4) == "member" && f.at(13) == "1")
      out.by_tick[tick].insert(std::stoi(f.at(2)));
  }
  return out;
}

// The share of the ticks in (from, to] seconds in which a camera other than `except` observes
// task 0's target (targets.csv's observed_by, from the evaluation).
double observed_share(const run_outcome& o, double tick_s, double from, double to, int except) {
  int ticks = 0;
  int observed = 0;
  for (const auto& row : o.evaluation.targets) {
    const double t = static_cast<double>(row.sample.tick) * tick_s;
    if (row.sample.task != 0 || t <= from || t > to) continue;
    ++ticks;
    observed += row.observed_by >= 0 && row.observed_by != except;
  }
  return ticks == 0 ? 0.0 : static_cast<double>(observed) / ticks;
}

// Section IV-C: a group outlives its leader. In each seed (the task on camera 7's next
// entrant, as in penn_station.yaml) the leader's camera crashes at the first moment after
// 20 s when one leader leads and a member has held her for a second: the group then has what
// it needs to go on. Every such seed must have a surviving leader within 10 s (the leader
// failure timeout is 3 s), and in most of them the survivors must observe her in the 10 s after
// the crash about as much as the whole group did without it (no more than 1.5 s less). Seeds in
// which nobody but the leader holds her are not crashed: whom the survivors' trackers hold there is
// the identification's matter, not the failure handling's (bench/RESULTS.md, "A leader's crash",
// has both).
TEST(leader_crash, a_group_keeps_her_through_its_leaders_crash) {
  constexpr int wanted = 8;
  constexpr double window_s = 10.0;
  int crashed = 0;
  int kept = 0;
  for (std::uint64_t seed = 1; seed <= 40 && crashed < wanted; ++seed) {
    SCOPED_TRACE(seed);
    auto calm = station(55.0, "argus_surveil_calm");
    calm.run.seed = seed;
    calm.network.node_failure_probability = 0.0;
    calm.tasks.at(0).by = config::task_target::first_to_enter;
    const auto before = run_scenario(calm, false);
    const auto events = events_of(before);
    const auto holds = members_holding_her(before.output_dir);
    std::optional<double> crash_s;
    int leader = 0;
    int held_for = 0;
    for (const auto& [tick, t] : holds.seconds) {
      const auto it = holds.by_tick.find(tick);
      held_for = it == holds.by_tick.end() ? 0 : held_for + 1;
      if (t < 20.0 || held_for < 15) continue;
      if (t > 55.0 - window_s) break;
      leader = leader_at(events, t);
      if (leader != 0 && it->second.count(leader) == 0) {
        crash_s = t;
        break;
      }
    }
    if (!crash_s) continue;
    auto s = calm;
    s.run.duration = config::seconds{*crash_s + window_s + 2.0};
    s.run.output_dir = (std::filesystem::temp_directory_path() / "argus_surveil_crash").string();
    s.faults.push_back({config::seconds{*crash_s}, config::fault_kind::crash, leader, std::nullopt,
                        config::seconds{0.0}, 1.0});
    const auto o = run_scenario(s, false);
    ++crashed;
    const auto after = leaders_at(events_of(o), *crash_s + window_s);
    EXPECT_FALSE(after.empty()) << "no camera leads the task 10 s after its leader crashed";
    EXPECT_EQ(after.count(leader), 0u);
    const auto& m = o.evaluation.tasks.at(0);
    ASSERT_EQ(m.failure_recoveries.size(), 1u);
    EXPECT_EQ(m.failure_recoveries[0].camera, leader);
    const double tick_s = s.run.tick.count();
    const double share = observed_share(o, tick_s, *crash_s, *crash_s + window_s, leader);
    const double calm_share = observed_share(before, tick_s, *crash_s, *crash_s + window_s, -1);
    std::printf(
        "seed %d: leader %d crashed at %.1f s; observed %.2f of the next 10 s (%.2f "
        "without the crash)\n",
        static_cast<int>(seed), leader, *crash_s, share, calm_share);
    kept += share >= calm_share - 0.15;
  }
  std::printf("leader crashes: %d, she was observed as without the crash (within 1.5 s): %d\n",
              crashed, kept);
  ASSERT_GE(crashed, 6);
  EXPECT_GE(3 * kept, 2 * crashed) << "the crash cost her observation in more than a third of "
                                      "the seeds";
}

}  // namespace
}  // namespace argus::actors
