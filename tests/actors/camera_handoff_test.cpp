// End to end on the real station (scenarios/penn_station*.yaml), on real threads: the
// operator's task at camera 7 is carried from camera to camera by the group, in both sensing
// modes, and the log shows every camera in at most one group at every tick.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>

#include "actors/run_scenario.hpp"
#include "config/scenario_loader.hpp"
#include "nlohmann/json.hpp"

namespace argus::actors {
namespace {

std::vector<nlohmann::json> run(const std::string& file, double seconds, const std::string& out,
                                std::optional<std::uint64_t> seed = std::nullopt) {
  auto s = config::load_scenario(std::filesystem::path(ARGUS_SOURCE_DIR) / "scenarios" / file);
  s.run.duration = config::seconds{seconds};
  if (seed) s.run.seed = *seed;
  s.run.threads = 2;
  s.run.output_dir = (std::filesystem::temp_directory_path() / out).string();
  run_scenario(s, false);
  // Every message the protocol sent is accounted for: delivered, lost, dropped or in flight.
  std::ifstream summary(std::filesystem::path(s.run.output_dir) / "summary.json");
  const auto sum = nlohmann::json::parse(summary);
  EXPECT_TRUE(sum["network"]["invariant_holds"].get<bool>());
  EXPECT_GT(sum["network"]["by_kind"]["status"]["delivered"].get<int>(), 0);
  std::vector<nlohmann::json> events;
  std::ifstream in(std::filesystem::path(s.run.output_dir) / "events.jsonl");
  for (std::string line; std::getline(in, line);) events.push_back(nlohmann::json::parse(line));
  return events;
}

std::size_t count(const std::vector<nlohmann::json>& events, const std::string& kind) {
  std::size_t n = 0;
  for (const auto& e : events) n += e["kind"] == kind ? 1 : 0;
  return n;
}

// Replays group membership from the log: a camera enters a group by task_created or joined,
// and leaves it by left_task; it must never enter a second group before leaving the first.
void expect_one_group_per_camera(const std::vector<nlohmann::json>& events) {
  std::map<int, std::optional<int>> in_group;
  for (const auto& e : events) {
    const std::string kind = e["kind"];
    if (kind != "task_created" && kind != "joined" && kind != "left_task") continue;
    const int camera = e["camera"];
    const int task = e["task"];
    if (kind == "left_task") {
      EXPECT_EQ(in_group[camera], task) << e.dump();
      in_group[camera].reset();
    } else {
      EXPECT_FALSE(in_group[camera].has_value()) << "camera in two groups at " << e.dump();
      in_group[camera] = task;
    }
  }
}

TEST(camera_handoff, the_group_carries_the_task_across_cameras_with_emulated_sensing) {
  const auto events = run("penn_station_emulated.yaml", 150.0, "argus_handoff_emulated");
  EXPECT_EQ(count(events, "task_created"), 1u);
  EXPECT_GE(count(events, "joined"), 2u);
  // A leader hands over at least once (members that left say so, and are never handed the
  // group, so the leader keeps it longer than when it handed it to departed members).
  EXPECT_GE(count(events, "handoff"), 1u);
  // Carried by at least three cameras in turn.
  std::set<int> carriers;
  for (const auto& e : events)
    if (e["kind"] == "task_created" || e["kind"] == "joined")
      carriers.insert(e["camera"].get<int>());
  EXPECT_GE(carriers.size(), 3u);
  expect_one_group_per_camera(events);
  // The task is still carried at the end: some camera leads it.
  std::map<int, int> leading;
  for (const auto& e : events) {
    if (e["kind"] == "task_created" ||
        (e["kind"] == "leader_changed" && e["leader"] == e["camera"]))
      leading[e["camera"]] = 1;
    if (e["kind"] == "left_task" && e["role"] == "leader") leading.erase(e["camera"].get<int>());
  }
  EXPECT_FALSE(leading.empty());
}

// The shipped pixel pipeline on degraded video (seed 1): camera 7 takes the next pedestrian to
// enter its view at 11.8 s, members join on what their own trackers find, and camera 7 hands
// the group to camera 8 at 23.4 s, camera 8 to camera 6 at 34.8 s. (Seed 8 was the example
// until the crowd's headway changed in issue 49: there the group now keeps its first leader.)
TEST(camera_handoff, the_group_carries_the_task_across_cameras_with_pixel_sensing) {
  const auto events = run("penn_station.yaml", 45.0, "argus_handoff_pixels", 1);
  EXPECT_EQ(count(events, "task_created"), 1u);
  EXPECT_GE(count(events, "bid"), 1u);
  EXPECT_GE(count(events, "joined"), 1u);
  EXPECT_GE(count(events, "handoff"), 1u);
  EXPECT_EQ(count(events, "render_failed"), 0u);
  expect_one_group_per_camera(events);
}

}  // namespace
}  // namespace argus::actors
