// End to end through the actor layer: a scenario built in code, run on real threads.

#include "actors/run_scenario.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "nlohmann/json.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::actors {
namespace {

config::scenario three_cameras(const std::filesystem::path& out) {
  config::scenario s;
  s.name = "three";
  s.run.seed = 3;
  s.run.duration = config::seconds{4.0};
  s.run.threads = 2;
  s.run.output_dir = out.string();
  for (int id : {1, 2, 3}) {
    config::camera_settings c;
    c.id = id;
    s.cameras.push_back(c);
  }
  config::operator_task task;
  task.at = config::seconds{0.5};
  task.pedestrian = 12;
  task.camera = 1;
  task.cameras_wanted = 2;
  s.tasks.push_back(task);
  config::fault recover;
  recover.at = config::seconds{1.0};
  recover.kind = config::fault_kind::crash_and_recover;
  recover.camera = 2;
  recover.length = config::seconds{1.0};
  s.faults.push_back(recover);
  config::fault crash;
  crash.at = config::seconds{2.0};
  crash.kind = config::fault_kind::crash;
  crash.camera = 3;
  s.faults.push_back(crash);
  config::fault cut;
  cut.at = config::seconds{1.5};
  cut.kind = config::fault_kind::link_cut;
  cut.camera = 1;
  cut.peer = 2;
  s.faults.push_back(cut);
  return s;
}

std::vector<nlohmann::json> events_of(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<nlohmann::json> out;
  for (std::string line; std::getline(in, line);) out.push_back(nlohmann::json::parse(line));
  return out;
}

// Pedestrian ids by tick, as trajectories.csv lists them (`tick,t,id,...`); a row listed twice
// shows up as a repeated id.
std::map<std::int64_t, std::multiset<int>> rows_by_tick(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::map<std::int64_t, std::multiset<int>> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string tick, t, id;
    std::getline(fields, tick, ',');
    std::getline(fields, t, ',');
    std::getline(fields, id, ',');
    rows[std::stoll(tick)].insert(std::stoi(id));
  }
  return rows;
}

// The pedestrians of world::crowd, the single-threaded reference, at ticks 0 to `ticks`.
std::map<std::int64_t, std::multiset<int>> reference_pedestrians(const config::scenario& s,
                                                                 std::int64_t ticks) {
  world::crowd reference(world::station::load(world::layout_path(s)),
                         world::crowd_settings::from(s));
  std::map<std::int64_t, std::multiset<int>> ids;
  for (std::int64_t k = 0; k <= ticks; ++k) {
    if (k > 0) reference.step();
    for (const auto& p : reference.current()->pedestrians()) ids[k].insert(p.id);
  }
  return ids;
}

TEST(run_scenario, runs_the_script_crashes_and_recovers_cameras_and_writes_outputs) {
  auto dir = std::filesystem::temp_directory_path() / ("argus-run-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  auto outcome = run_scenario(three_cameras(dir), false);
  EXPECT_EQ(outcome.result.ticks, 60);  // 4 s at 15 Hz
  EXPECT_TRUE(outcome.result.unexpected_down.empty());
  auto events = events_of(dir / "events.jsonl");
  auto find = [&](const std::string& kind, double t) {
    return std::count_if(events.begin(), events.end(), [&](const nlohmann::json& e) {
      return e["kind"] == kind && std::abs(e["t"].get<double>() - t) < 1e-6;
    });
  };
  EXPECT_EQ(find("node_up", 0.0), 3);
  EXPECT_EQ(find("task_issued", 8.0 / 15.0), 1);
  EXPECT_EQ(find("fault", 1.0), 1);
  EXPECT_EQ(find("node_recovered", 2.0), 1);
  // The recovered camera comes back empty-handed and announces itself on its first tick.
  EXPECT_EQ(find("node_up", 2.0), 1);
  EXPECT_EQ(find("fault", 2.0), 1);
  // Link faults reach the link between the two cameras.
  auto cut = std::find_if(events.begin(), events.end(), [](const nlohmann::json& e) {
    return e.value("fault", "") == "link_cut";
  });
  ASSERT_NE(cut, events.end());
  EXPECT_EQ((*cut)["applied"], true);
  // Events are in time order.
  for (std::size_t i = 1; i < events.size(); ++i)
    EXPECT_LE(events[i - 1]["tick"].get<int>(), events[i]["tick"].get<int>());
  std::ifstream summary_in(dir / "summary.json");
  auto summary = nlohmann::json::parse(summary_in);
  EXPECT_EQ(summary["ticks"], 60);
  EXPECT_EQ(summary["events_total"], events.size());
  // 3 cameras, 3 links (all within range), the script, the fault injector, 1 recovered camera,
  // 1 crowd partition and the world coordinator.
  EXPECT_EQ(summary["participants"], 11);
  // The crowd's ground truth, one row per pedestrian per tick (ticks 0 to 60): the same
  // pedestrians, each once, as the reference crowd has at every tick.
  ASSERT_TRUE(std::filesystem::exists(dir / "trajectories.csv"));
  const auto rows = rows_by_tick(dir / "trajectories.csv");
  const auto expected = reference_pedestrians(three_cameras(dir), 60);
  ASSERT_EQ(rows.size(), 61u);
  ASSERT_GT(expected.at(0).size(), 0u);
  for (const auto& [tick, ids] : expected) {
    const auto listed = rows.count(tick) ? rows.at(tick) : std::multiset<int>{};
    EXPECT_EQ(listed, ids) << "tick " << tick << ": " << listed.size() << " rows for " << ids.size()
                           << " pedestrians";
  }
  // Who looks like what: every pedestrian of the trajectories once, at the tick first listed.
  ASSERT_TRUE(std::filesystem::exists(dir / "pedestrians.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "pedestrians.csv.partial"));
  std::map<int, std::int64_t> first_listed;
  for (const auto& [tick, ids] : rows)
    for (int id : ids) first_listed.emplace(id, tick);
  std::map<int, std::int64_t> first_written;
  std::ifstream looks(dir / "pedestrians.csv");
  std::string look;
  std::getline(looks, look);  // header
  while (std::getline(looks, look)) {
    std::istringstream fields(look);
    std::string id, tick;
    std::getline(fields, id, ',');
    std::getline(fields, tick, ',');
    EXPECT_TRUE(first_written.emplace(std::stoi(id), std::stoll(tick)).second) << look;
  }
  EXPECT_EQ(first_written, first_listed);
  EXPECT_EQ(summary["network"]["links"], 3);
  EXPECT_GT(summary["network"]["totals"]["delivered"].get<int>(), 0);
  EXPECT_EQ(summary["network"]["invariant_holds"], true);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace argus::actors
