// Persistent surveillance end to end (Section V), measured against ground truth on real
// threads: the target is carried across cameras (a leader's crash: leader_crash_test), the
// strategies rank as they must, the operator ends a task, and the MOTChallenge files obey the
// format's rules. Emulated sensing keeps each run under a second.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "actors/run_scenario.hpp"
#include "config/enum_names.hpp"
#include "config/scenario_loader.hpp"
#include "eval/mot_export.hpp"
#include "nlohmann/json.hpp"
#include "surveillance_runs.hpp"
#include "tests/support/csp_log_check.hpp"

namespace argus::actors {
namespace {

using surveillance_runs::events_of;
using surveillance_runs::station;

TEST(surveillance, the_target_is_observed_by_three_cameras_in_turn) {
  const auto o = run_scenario(station(150.0, "argus_surveil_carry"), false);
  ASSERT_EQ(o.evaluation.tasks.size(), 1u);
  const auto& m = o.evaluation.tasks[0];
  EXPECT_EQ(m.pedestrian, 21);
  EXPECT_GT(m.time_in_station_s, 100.0);
  EXPECT_GT(m.oracle_bound, 0.9);
  EXPECT_GT(m.coverage, 0.25);
  EXPECT_GE(m.observation_handoffs, 2);
  std::set<int> observers;
  for (const auto& row : o.evaluation.targets)
    if (row.observed_by >= 0) observers.insert(row.observed_by);
  EXPECT_GE(observers.size(), 3u);
  for (const auto* file : {"metrics.json", "tracks.csv", "targets.csv", "poses.csv"})
    EXPECT_TRUE(std::filesystem::exists(o.output_dir / file)) << file;
}

// Per tick, the cameras that hold task 0's target as members (tracks.csv: role member,

TEST(surveillance, the_oracle_bounds_the_protocol_and_the_protocol_beats_working_alone) {
  std::map<std::string, double> coverage;
  for (std::string strategy : {"paper", "oracle", "no_collaboration"}) {
    auto s = station(120.0, "argus_surveil_strategy");
    s.controller.strategy = strategy;
    coverage[strategy] = run_scenario(s, false).evaluation.tasks.at(0).coverage;
  }
  EXPECT_GT(coverage["oracle"], coverage["paper"]);
  EXPECT_GT(coverage["paper"], coverage["no_collaboration"]);
}

TEST(surveillance, a_cancelled_task_is_left_by_every_camera) {
  auto s = station(90.0, "argus_surveil_cancel");
  s.tasks.at(0).cancel_at = config::seconds{50.0};
  const auto o = run_scenario(s, false);
  const auto& m = o.evaluation.tasks.at(0);
  EXPECT_EQ(m.end_reason, "cancelled");
  EXPECT_NEAR(m.end_s, 50.0, 0.1);
  // Nobody performs it 5 s after the cancellation (messages take up to 0.5 s a hop).
  std::ifstream tracks(o.output_dir / "tracks.csv");
  std::string line;
  std::getline(tracks, line);
  int late = 0;
  while (std::getline(tracks, line)) late += std::stod(line.substr(line.find(',') + 1)) > 55.0;
  EXPECT_EQ(late, 0);
  int cancelled = 0;
  for (const auto& e : events_of(o))
    cancelled += e["kind"] == "left_task" && e["reason"] == "cancelled";
  EXPECT_GE(cancelled, 1);
}

TEST(surveillance, an_automatic_task_takes_the_first_pedestrian_to_enter) {
  auto s = station(30.0, "argus_surveil_entry");
  s.tasks.at(0).by = config::task_target::first_to_enter;
  s.tasks.at(0).at = config::seconds{2.0};
  const auto o = run_scenario(s, false);
  const auto events = events_of(o);
  int targets = 0;
  for (const auto& e : events)
    if (e["kind"] == "task_target") {
      ++targets;
      EXPECT_EQ(e["by"], "first_to_enter");
      EXPECT_GT(e["t"].get<double>(), 2.0);
    }
  EXPECT_EQ(targets, 1);
  ASSERT_EQ(o.evaluation.tasks.size(), 1u);
  EXPECT_GT(o.evaluation.tasks[0].coverage, 0.0);
}

TEST(surveillance, the_operator_clicks_on_a_pedestrian_or_on_nobody) {
  // Where pedestrian 21 appears in camera 7's idle view at the click (tick 151, 10 s + one
  // tick), from the ground truth of a run whose task comes too late to move the camera.
  constexpr int click_tick = 151;
  auto idle = station(11.0, "argus_surveil_click_truth");
  idle.tasks.at(0).at = config::seconds{100.0};
  run_options options;
  options.mot = true;
  const auto truth = run_scenario(idle, options);
  std::ifstream gt(truth.output_dir / "mot/gt/mot_challenge/ARGUS-all/cam07/gt/gt.txt");
  std::optional<std::pair<double, double>> centre;
  for (std::string line; std::getline(gt, line);) {
    std::vector<double> f;
    std::stringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(std::stod(x));
    if (f[0] == click_tick + 1 && f[1] == 21) centre = {f[2] + f[4] / 2.0, f[3] + f[5] / 2.0};
  }
  ASSERT_TRUE(centre.has_value()) << "pedestrian 21 is not in camera 7's view at the click";
  const auto [x, y] = *centre;
  auto s = station(11.0, "argus_surveil_click");
  auto& t = s.tasks.at(0);
  t.by = config::task_target::pixel;
  t.pixel = {x, y};
  t.at = config::seconds{click_tick / 15.0};
  auto nobody = t;
  nobody.pixel = {2.0, 2.0};  // the ceiling
  s.tasks.push_back(nobody);
  int clicked = 0, refused = 0;
  for (const auto& e : events_of(run_scenario(s, false))) {
    if (e["kind"] == "task_target") {
      // Whoever is nearest the camera under the click: her, or someone in front of her.
      ++clicked;
      EXPECT_GE(e["pedestrian"].get<int>(), 1);
      EXPECT_EQ(e["by"], "pixel");
      EXPECT_EQ(e["task"], 0);
    }
    if (e["kind"] == "task_refused") {
      ++refused;
      EXPECT_EQ(e["reason"], "no_pedestrian_at_pixel");
      EXPECT_EQ(e["task"], 1);
    }
  }
  EXPECT_EQ(clicked, 1);
  EXPECT_EQ(refused, 1);
}

// Fig. 19: camera 2 takes the first pedestrian to enter its view and camera 1 joins it; a
// second task arrives through camera 1, which leaves the first group to lead it and, claimed by
// two groups, initiates conflict resolution. Camera 2 (the lower task's leader) centralises the
// CSP, both cameras weighed for both tasks, and each camera takes its place in the optimum.
// Seed 2: the first group still has both cameras when the second task comes (in seed 1 camera
// 2 has already lost her and handed the group to camera 1, which the operator then takes).
TEST(surveillance, fig_19_two_tasks_are_settled_by_the_csp) {
  auto s =
      config::load_scenario(std::filesystem::path(ARGUS_SOURCE_DIR) / "scenarios/two_tasks.yaml");
  s.sensing.mode = config::sensing_mode::emulated;
  s.run.seed = 2;
  s.run.threads = 2;
  s.run.output_dir = (std::filesystem::temp_directory_path() / "argus_surveil_fig19").string();
  const auto o = run_scenario(s, false);
  ASSERT_EQ(o.evaluation.tasks.size(), 2u);
  bool joined_first = false, left_for_second = false, leads_second = false, reported = false;
  std::optional<nlohmann::json> solved;
  std::map<int, int> applied;  // camera -> its task in the first result it took
  for (const auto& e : events_of(o)) {
    const int camera = e.value("camera", 0);
    if (camera == 1 && e["kind"] == "joined" && e["task"] == 0) joined_first = true;
    if (camera == 1 && e["kind"] == "left_task" && e["task"] == 0 && e["reason"] == "operator")
      left_for_second = joined_first;
    if (camera == 1 && e["kind"] == "task_created" && e["task"] == 1)
      leads_second = left_for_second;
    if (camera == 1 && e["kind"] == "conflict_reported" && leads_second) {
      reported = true;
      EXPECT_EQ(e["tasks"], nlohmann::json::array({0, 1}));
      EXPECT_EQ(e["to"], 2);
    }
    if (e["kind"] == "csp_solved" && !solved) {
      EXPECT_EQ(camera, 2);
      solved = e;
    }
    if (e["kind"] == "csp_applied" && solved && applied.count(camera) == 0)
      applied[camera] = e["task"].get<int>();
  }
  EXPECT_TRUE(leads_second);
  EXPECT_TRUE(reported);
  ASSERT_TRUE(solved.has_value());
  // Both cameras were weighed for both tasks' groups, and the answer is the optimum.
  EXPECT_EQ((*solved)["camera_ids"], nlohmann::json::array({1, 2}));
  EXPECT_EQ((*solved)["tasks"], nlohmann::json::array({0, 1}));
  argus::testing::expect_optimal(*solved, s.controller.membership_relevance_threshold);
  // Each camera took the place the answer gave it.
  const auto leaders = (*solved)["leaders"].get<std::vector<int>>();
  ASSERT_EQ(leaders.size(), 2u);
  EXPECT_EQ(applied[leaders[0]], 0);
  EXPECT_EQ(applied[leaders[1]], 1);
  EXPECT_GT(o.evaluation.tasks[0].coverage, 0.0);
  EXPECT_GT(o.evaluation.tasks[1].coverage, 0.0);
}

// MOTChallenge's rules for gt.txt (9 columns) and tracker files (10 columns): integer frames
// from 1 to seqLength, integer ids >= 1, positive sizes, one box per id per frame.
void expect_mot_file(const std::filesystem::path& file, std::size_t columns, int frames,
                     bool ground_truth) {
  std::ifstream in(file);
  ASSERT_TRUE(in) << file;
  std::set<std::pair<int, int>> seen;
  int rows = 0;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> v;
    std::stringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) v.push_back(std::stod(f));
    ASSERT_EQ(v.size(), columns) << file << ": " << line;
    const int frame = static_cast<int>(v[0]);
    const int id = static_cast<int>(v[1]);
    EXPECT_EQ(frame, v[0]);
    EXPECT_EQ(id, v[1]);
    EXPECT_GE(frame, 1);
    EXPECT_LE(frame, frames);
    EXPECT_GE(id, 1);
    EXPECT_GT(v[4], 0.0);
    EXPECT_GT(v[5], 0.0);
    EXPECT_TRUE(seen.emplace(frame, id).second) << "two boxes for one id in " << line;
    if (ground_truth) {
      EXPECT_EQ(v[6], 1.0);
      EXPECT_EQ(v[7], 1.0);
      EXPECT_GE(v[8], 0.0);
      EXPECT_LE(v[8], 1.0);
    } else {
      EXPECT_EQ(v[7], -1.0);
    }
    ++rows;
  }
  if (ground_truth) {
    EXPECT_GT(rows, 0) << file;
  }
}

TEST(surveillance, the_mot_export_obeys_the_format) {
  run_options options;
  options.mot = true;
  const auto o = run_scenario(station(20.0, "argus_surveil_mot"), options);
  const int frames = 300;
  const auto gt = o.output_dir / "mot/gt/mot_challenge";
  std::ifstream seqmap(gt / "seqmaps/ARGUS-all.txt");
  std::string line;
  std::getline(seqmap, line);
  EXPECT_EQ(line, "name");
  int sequences = 0;
  int tracked = 0;
  while (std::getline(seqmap, line)) {
    ++sequences;
    std::ifstream ini(gt / "ARGUS-all" / line / "seqinfo.ini");
    std::stringstream text;
    text << ini.rdbuf();
    EXPECT_NE(text.str().find("seqLength=300\n"), std::string::npos) << text.str();
    EXPECT_NE(text.str().find("frameRate=15\n"), std::string::npos);
    expect_mot_file(gt / "ARGUS-all" / line / "gt/gt.txt", 9, frames, true);
    const auto tracker =
        o.output_dir / "mot/trackers/mot_challenge/ARGUS-all/argus/data" / (line + ".txt");
    expect_mot_file(tracker, 10, frames, false);
    tracked += std::filesystem::file_size(tracker) > 0;
  }
  EXPECT_EQ(sequences, 16);
  EXPECT_GE(tracked, 1);
}

}  // namespace
}  // namespace argus::actors
