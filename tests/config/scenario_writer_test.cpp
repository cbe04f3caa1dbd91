#include "config/scenario_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "config/scenario_loader.hpp"

namespace argus::config {
namespace {

using namespace std::chrono_literals;

const std::filesystem::path data_dir{ARGUS_CONFIG_TEST_DATA_DIR};

/// Writes `original` and reads it back; source_path is not part of the text.
scenario round_trip(const scenario& original) {
  auto back = parse_scenario(to_yaml(original), "written.yaml");
  back.source_path = original.source_path;
  return back;
}

/// Section by section first, so a failure says which part was lost.
void expect_same(const scenario& back, const scenario& original) {
  EXPECT_EQ(back.name, original.name);
  EXPECT_EQ(back.run, original.run);
  EXPECT_EQ(back.world, original.world);
  EXPECT_EQ(back.cameras, original.cameras);
  EXPECT_EQ(back.network, original.network);
  EXPECT_EQ(back.controller, original.controller);
  EXPECT_EQ(back.tasks, original.tasks);
  EXPECT_EQ(back.faults, original.faults);
  EXPECT_EQ(back, original);
}

TEST(scenario_writer, round_trips_a_full_scenario) {
  // full.yaml sets every field away from its default, so a field the writer forgot would
  // come back as the default and differ.
  const auto original = load_scenario(data_dir / "full.yaml");
  expect_same(round_trip(original), original);
}

TEST(scenario_writer, round_trips_the_bound_solv_solver) {
  const auto original = parse_scenario("controller: {solver: bound_solv}\n", "defaults.yaml");
  EXPECT_NE(to_yaml(original).find("\n  solver: bound_solv\n"), std::string::npos);
  expect_same(round_trip(original), original);
}

TEST(scenario_writer, round_trips_a_defaults_only_scenario) {
  const auto original = parse_scenario("", "defaults.yaml");
  expect_same(round_trip(original), original);
}

TEST(scenario_writer, round_trips_awkward_values_exactly) {
  scenario original;
  original.name = "a: tricky # name \"quoted\"";
  original.run.tick = seconds{1.0 / 15.0};
  original.run.duration = seconds{0.1 + 0.2};
  original.run.seed = 18446744073709551615u;
  original.run.speed = 1.0 / 3.0;
  original.world.layout = "null";
  camera_settings camera;
  camera.id = 5;
  camera.position = {-1e-9, 12345.678};
  // Parameters set but switched off must survive too.
  camera.imaging.color_response_enabled = false;
  camera.imaging.response.tint = 0.25;
  original.cameras.push_back(camera);
  original.faults.push_back(fault{1.5s, fault_kind::crash, 5, std::nullopt, 0s, 1.0});
  operator_task by_id;
  by_id.at = seconds{2.0 / 3.0};
  by_id.pedestrian = 4;
  by_id.camera = 5;
  original.tasks.push_back(by_id);
  operator_task by_pixel;
  by_pixel.at = 3s;
  by_pixel.by = task_target::pixel;
  by_pixel.pixel = {160.5, 1.0 / 3.0};
  by_pixel.camera = 5;
  by_pixel.cancel_at = seconds{10.0 / 3.0};
  original.tasks.push_back(by_pixel);
  operator_task by_entry;
  by_entry.by = task_target::first_to_enter;
  by_entry.camera = 5;
  by_entry.cameras_wanted = 2;
  by_entry.max_cameras = 3;
  original.tasks.push_back(by_entry);
  original.controller.strategy = "oracle";
  original.controller.oracle_signature_from = oracle_signature::operator_pick;
  original.controller.oracle_zoom = false;
  original.sensing.ego_motion = true;
  original.sensing.signature_update = true;
  original.sensing.reacquire_margin = 0.05;
  original.sensing.local_search_frames = 30;
  original.sensing.max_surround_match = 0.65;
  original.sensing.surround_grace_frames = 15;
  original.sensing.surround_grace_height_px = 40;
  original.sensing.surround_patience_frames = 2;
  original.sensing.surround_sides = 3;
  original.sensing.track_rho = 0.3;
  original.sensing.halves_rho = 0.45;
  original.controller.share_model = true;
  original.sensing.identity = identity_source::ground_truth;
  original.sensing.geometry = group_geometry::ground_truth;
  original.sensing.reappearance = reappearance_model::ground_truth;
  original.controller.bid_evidence_time = config::seconds{1.0};
  original.controller.bid_min_found_fraction = 0.6;
  original.controller.bid_min_mean_score = 0.5;
  original.controller.zoom_in_track = false;
  original.controller.track_while_bidding = true;
  expect_same(round_trip(original), original);
}

TEST(scenario_writer, writes_defaults_durations_and_enums_readably) {
  const auto text = to_yaml(parse_scenario("", "defaults.yaml"));
  EXPECT_NE(text.find("\n  tick: 1/15 s\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  message_timeout: 1500 ms\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  min_delay: 200 ms\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  hello_interval: 1 s\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  neighbour_timeout: 5 s\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  unicast: flood\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  wait_timeout: 2 min\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  solver: optimistic_solv\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  output_dir: \"\"\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\ncameras: []\n"), std::string::npos) << text;
}

TEST(scenario_writer, writes_a_camera_with_every_field) {
  const auto text =
      to_yaml(parse_scenario("cameras:\n  - {id: 2, position: [1, 2], type: static}\n", "x.yaml"));
  EXPECT_NE(text.find("  - id: 2\n    position: {x_m: 1, y_m: 2}\n    height_m: 4\n    type: "
                      "static\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\n      color_response: off\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n      dropout: {fraction: 0, kind: snow}\n"), std::string::npos) << text;
}

// A worker reads its coordinator's to_yaml in one pass (parse_written_scenario): it must come
// back as the file's own reader gives it, every field.
TEST(scenario_writer, the_one_pass_reader_reads_what_the_writer_wrote) {
  const auto original = load_scenario(data_dir / "full.yaml");
  auto back = parse_written_scenario(to_yaml(original), "written.yaml");
  back.source_path = original.source_path;
  expect_same(back, original);
}

TEST(scenario_writer, the_one_pass_reader_names_a_syntax_error_as_the_file_reader_does) {
  const auto problems_of = [](auto read) -> std::vector<problem> {
    try {
      read("name: a\nrun: {seed: 1\n", "the coordinator's scenario");
    } catch (const scenario_error& e) {
      return e.problems();
    }
    return {};
  };
  const auto one_pass =
      problems_of([](auto text, auto name) { return parse_written_scenario(text, name); });
  ASSERT_EQ(one_pass.size(), 1u);
  EXPECT_EQ(one_pass[0].file, "the coordinator's scenario");
  EXPECT_GT(one_pass[0].line, 0);
  EXPECT_EQ(one_pass, problems_of([](auto text, auto name) { return parse_scenario(text, name); }));
}

// parse_scenario's guard against yaml-cpp's endless documents (a stray ',') costs a pass of its
// own; the one-pass reader reads one document, so the same text ends at once.
TEST(scenario_writer, the_one_pass_reader_ends_on_a_stray_comma) {
  EXPECT_EXIT(
      {
        alarm(20);
        try {
          parse_written_scenario("- 1\n,\n", "comma.yaml");
        } catch (const scenario_error&) {
        }
        std::exit(0);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace argus::config
