// The instruments of the surveillance experiments, end to end on real threads: the oracle's
// ablations (no zoom, the operator's signature), the ground-truth stand-ins for a learned
// geometry, a reappearance model and a perfect identity test. Apart from surveillance_test so
// that neither binary nears its timeout under ThreadSanitizer.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "actors/run_scenario.hpp"
#include "config/enum_names.hpp"
#include "config/scenario_loader.hpp"
#include "report/camera_logs.hpp"
#include "surveillance_runs.hpp"

namespace argus::actors {
namespace {

using surveillance_runs::events_of;
using surveillance_runs::station;

// controller.oracle_zoom: false points the oracle's cameras at her with their default field of
// view: no camera's field of view ever leaves its default, where the oracle as first built
// zooms every camera it assigns.
TEST(surveillance_instruments, the_oracle_without_zoom_keeps_every_default_field_of_view) {
  std::map<bool, int> zoomed_rows;
  for (bool zoom : {true, false}) {
    auto s = station(60.0, "argus_surveil_oracle_zoom");
    s.controller.strategy = "oracle";
    s.controller.oracle_zoom = zoom;
    const auto o = run_scenario(s, false);
    std::map<int, double> home;
    for (const auto& c : s.cameras) home[c.id] = c.field_of_view_deg;
    const auto poses = report::pose_history::read(o.output_dir / "poses.csv");
    for (int camera : poses.cameras())
      for (const auto& pose : poses.rows_of(camera))
        zoomed_rows[zoom] += std::abs(pose.field_of_view_deg - home.at(camera)) > 1e-6;
    EXPECT_GT(o.evaluation.tasks.at(0).coverage, 0.0) << zoom;
  }
  EXPECT_GT(zoomed_rows[true], 0);
  EXPECT_EQ(zoomed_rows[false], 0);
}

// controller.oracle_signature: operator gives every oracle camera the signature of the
// operator's pick (on pixels, where a camera's own view of her differs from it): the cameras
// still find her with it, and what they find differs from the run with their own views'.
TEST(surveillance_instruments, the_oracle_can_look_with_the_operators_signature) {
  std::map<config::oracle_signature, std::string> tracks;
  for (auto from : {config::oracle_signature::own_view, config::oracle_signature::operator_pick}) {
    auto s = config::load_scenario(std::filesystem::path(ARGUS_SOURCE_DIR) /
                                   "scenarios/penn_station.yaml");
    s.run.duration = config::seconds{30.0};
    s.run.threads = 2;
    s.run.output_dir =
        (std::filesystem::temp_directory_path() / "argus_surveil_oracle_signature").string();
    s.controller.strategy = "oracle";
    s.controller.oracle_signature_from = from;
    const auto o = run_scenario(s, false);
    EXPECT_GT(o.evaluation.tasks.at(0).coverage, 0.0) << config::yaml_name(from);
    std::ifstream in(o.output_dir / "tracks.csv");
    std::stringstream text;
    text << in.rdbuf();
    tracks[from] = text.str();
  }
  EXPECT_GT(tracks[config::oracle_signature::operator_pick].size(), 100u);
  EXPECT_NE(tracks[config::oracle_signature::own_view],
            tracks[config::oracle_signature::operator_pick]);
}

// How many times a queried camera zoomed in while bidding (state computing_relevance, field of
// view below its default) within 1 s of the query, from the run's events and poses.csv. With
// `unfound_only`, only queries whose bid says the camera never found her (found_fraction 0):
// a bidder that finds her fixates and zooms on her, in the paper's controller too.
int bidders_that_zoomed(const run_outcome& o, const config::scenario& s,
                        bool unfound_only = false) {
  const auto one_second = static_cast<std::int64_t>(std::lround(1.0 / s.run.tick.count()));
  std::map<int, double> home;
  for (const auto& c : s.cameras) home[c.id] = c.field_of_view_deg;
  const auto events = events_of(o);
  std::multimap<int, std::int64_t> queried;  // camera -> world tick
  for (std::size_t i = 0; i < events.size(); ++i) {
    const auto& e = events[i];
    if (e["kind"] != "queried") continue;
    const int camera = e["camera"].get<int>();
    if (unfound_only) {
      bool found = false;
      for (std::size_t j = i + 1; j < events.size(); ++j) {
        if (events[j]["kind"] == "bid" && events[j]["camera"] == camera) {
          found = events[j]["found_fraction"].get<double>() > 0.0;
          break;
        }
      }
      if (found) continue;
    }
    queried.emplace(camera, e["tick"].get<std::int64_t>());
  }
  const auto poses = report::pose_history::read(o.output_dir / "poses.csv");
  std::set<std::pair<int, std::int64_t>> zoomed;
  for (int camera : poses.cameras())
    for (const auto& pose : poses.rows_of(camera)) {
      if (pose.state != "computing_relevance") continue;
      if (pose.field_of_view_deg >= home.at(camera) - 1e-6) continue;
      auto [first, last] = queried.equal_range(camera);
      for (auto it = first; it != last; ++it)
        if (pose.world_tick > it->second && pose.world_tick <= it->second + one_second)
          zoomed.insert({camera, it->second});
    }
  return static_cast<int>(zoomed.size());
}

// sensing.group_geometry and sensing.reappearance: ground_truth: a queried camera that has not
// found her is pointed and zoomed where the group sees her, or where she is once the group holds
// nobody, where the paper's holds its pose while it looks; and the run stays the same whatever
// the thread count (nodes read only the last frame's sightings).
TEST(surveillance_instruments, with_the_groups_geometry_bidders_turn_to_where_the_group_sees_her) {
  auto paper = station(90.0, "argus_surveil_geometry");
  const auto held = run_scenario(paper, false);
  const int paper_zoomed = bidders_that_zoomed(held, paper, true);
  const auto paper_events = events_of(held);
  auto geometry = paper;
  geometry.sensing.geometry = config::group_geometry::ground_truth;
  // Pointed where the group sees her, a bidder usually finds her: count all of its zooms.
  const int geometry_zoomed = bidders_that_zoomed(run_scenario(geometry, false), geometry);
  std::printf("bidders that zoomed: paper %d (and never found her), group geometry %d\n",
              paper_zoomed, geometry_zoomed);
  // The paper's may zoom on a lookalike it loses again (found_fraction 0): seen once in this
  // run since issue 49's crowd.
  EXPECT_LE(paper_zoomed, 1);
  EXPECT_GT(geometry_zoomed, 3 * paper_zoomed);
  // The reappearance points mostly members that lost her (a bidder is queried while the group
  // holds someone), which poses.csv does not tell from tracking: sighting_board_test has its
  // rule; here, that it acts at all.
  auto reappearance = paper;
  reappearance.sensing.reappearance = config::reappearance_model::ground_truth;
  EXPECT_NE(events_of(run_scenario(reappearance, false)), paper_events);
  auto both = geometry;
  both.sensing.reappearance = config::reappearance_model::ground_truth;
  const auto reference = events_of(run_scenario(both, false));
  for (unsigned threads : {1u, 4u}) {
    both.run.threads = threads;
    EXPECT_EQ(events_of(run_scenario(both, false)), reference) << threads << " threads";
  }
}

// sensing.group_geometry: calibrated: a queried camera that has not found her is pointed and
// zoomed at where its group's calibrated cameras put her on the floor (the paper's holds its
// pose while it looks: the test above), and the run stays the same whatever the thread count
// (nodes read only earlier frames' estimates). The gate's rule is floor_estimate_test's.
TEST(surveillance_instruments, calibrated_cameras_turn_bidders_to_where_the_group_puts_her) {
  auto calibrated = station(90.0, "argus_surveil_calibrated");
  calibrated.sensing.geometry = config::group_geometry::calibrated;
  const auto first = run_scenario(calibrated, false);
  EXPECT_GT(bidders_that_zoomed(first, calibrated), 0);
  const auto reference = events_of(first);
  calibrated.run.threads = 4;
  EXPECT_EQ(events_of(run_scenario(calibrated, false)), reference);
}

// sensing.identity: ground_truth takes away the cameras' mistakes of identity and nothing else:
// with it no group member's box is ever on someone else while she goes unobserved, and nearly
// every box found for the task is hers; the same run with the paper's cameras follows others.
TEST(surveillance_instruments, with_identity_from_ground_truth_the_group_follows_nobody_else) {
  std::map<config::identity_source, eval::task_metrics> task;
  for (auto identity :
       {config::identity_source::appearance, config::identity_source::ground_truth}) {
    auto s = station(120.0, "argus_surveil_identity");
    s.sensing.identity = identity;
    task[identity] = run_scenario(s, false).evaluation.tasks.at(0);
  }
  const auto& truth = task[config::identity_source::ground_truth];
  const auto& paper = task[config::identity_source::appearance];
  EXPECT_LT(truth.uncovered.other_person, 0.01);
  ASSERT_TRUE(truth.correct_identity.has_value());
  EXPECT_GT(*truth.correct_identity, 0.9);
  EXPECT_GT(paper.uncovered.other_person, 0.1);
  EXPECT_GT(truth.coverage, paper.coverage);
}

}  // namespace
}  // namespace argus::actors
