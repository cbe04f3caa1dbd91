#include <gtest/gtest.h>

#include <filesystem>

#include "config/scenario_loader.hpp"

// Each test feeds one kind of bad input and checks the exact problem: file, line, column,
// field and message. Line and column are 1-based and point at the offending value (or at
// the mapping that lacks a required key).

namespace argus::config {

/// Lets GoogleTest print a problem as the user would see it (inline: the folder's tests link
/// into one executable, and scenario_loader_test.cpp has the same).
inline void PrintTo(const problem& what, std::ostream* out) {
  *out << to_string(what);
}

namespace {

const std::filesystem::path data_dir{ARGUS_CONFIG_TEST_DATA_DIR};

std::vector<problem> problems_in(const std::string& yaml) {
  try {
    parse_scenario(yaml, "bad.yaml");
  } catch (const scenario_error& error) {
    return error.problems();
  }
  return {};
}

/// The one problem in `yaml`; an empty problem (failing every check) if there is not
/// exactly one.
problem only_problem(const std::string& yaml) {
  const auto problems = problems_in(yaml);
  EXPECT_EQ(problems.size(), 1u) << ::testing::PrintToString(problems.size()) << " problems";
  return problems.size() == 1 ? problems[0] : problem{};
}

const std::string one_camera = "cameras:\n  - {id: 1, position: [0, 0]}\n";

TEST(scenario_validation, unknown_key_suggests_the_closest_known_key) {
  const auto file = data_dir / "unknown_key.yaml";
  try {
    load_scenario(file);
    FAIL() << "no scenario_error";
  } catch (const scenario_error& error) {
    ASSERT_EQ(error.problems().size(), 1u);
    EXPECT_EQ(error.problems()[0],
              (problem{file.string(), 3, 3, "run.speeed",
                       "unknown key 'speeed' (expected one of: seed, duration, tick, speed, "
                       "threads, output_dir); did you mean 'speed'?"}));
    EXPECT_EQ(std::string{error.what()},
              file.string() +
                  ":3:3: run.speeed: unknown key 'speeed' (expected one of: seed, duration, "
                  "tick, speed, threads, output_dir); did you mean 'speed'?");
  }
}

TEST(scenario_validation, unknown_key_without_a_close_match_gets_no_suggestion) {
  EXPECT_EQ(
      only_problem("world: {colour: red}\n"),
      (problem{"bad.yaml", 1, 9, "world.colour",
               "unknown key 'colour' (expected one of: layout, population, "
               "spawn_rate_per_min, partitions, speed, clothing, flows, measurement_areas)"}));
}

TEST(scenario_validation, unknown_top_level_key) {
  EXPECT_EQ(only_problem("name: x\ncamera: []\n"),
            (problem{"bad.yaml", 2, 1, "camera",
                     "unknown key 'camera' (expected one of: name, run, world, cameras, network, "
                     "controller, sensing, tasks, faults, placement); did you mean 'cameras'?"}));
}

TEST(scenario_validation, where_the_crowd_steps_is_one_of_two_places) {
  EXPECT_EQ(only_problem(one_camera + "placement: {crowd: cloud}\n"),
            (problem{"bad.yaml", 3, 20, "placement.crowd",
                     "expected one of: workers, coordinator, got 'cloud'"}));
  EXPECT_TRUE(problems_in(one_camera + "placement: {crowd: coordinator}\n").empty());
}

TEST(scenario_validation, a_key_given_twice) {
  EXPECT_EQ(
      only_problem("run:\n  seed: 1\n  seed: 2\n"),
      (problem{"bad.yaml", 3, 3, "run.seed", "duplicate key 'seed' (first given at line 2)"}));
}

TEST(scenario_validation, wrong_type_integer) {
  EXPECT_EQ(only_problem("run:\n  seed: abc\n"),
            (problem{"bad.yaml", 2, 9, "run.seed", "expected a non-negative integer, got 'abc'"}));
  EXPECT_EQ(
      only_problem("run: {threads: -1}\n"),
      (problem{"bad.yaml", 1, 16, "run.threads", "expected a non-negative integer, got '-1'"}));
  EXPECT_EQ(only_problem("cameras:\n  - {id: x1, position: [0, 0]}\n"),
            (problem{"bad.yaml", 2, 10, "cameras[0].id", "expected an integer, got 'x1'"}));
}

TEST(scenario_validation, wrong_type_duration_without_unit) {
  EXPECT_EQ(only_problem("network:\n  message_timeout: 1500\n"),
            (problem{"bad.yaml", 2, 20, "network.message_timeout",
                     "expected a duration with a unit, e.g. '1500 ms', got '1500'"}));
}

TEST(scenario_validation, wrong_type_number_bool_mapping_and_list) {
  EXPECT_EQ(only_problem("run: {speed: fast}\n"),
            (problem{"bad.yaml", 1, 14, "run.speed", "expected a number, got 'fast'"}));
  EXPECT_EQ(only_problem("network: {reorder: maybe}\n"),
            (problem{"bad.yaml", 1, 20, "network.reorder", "expected true or false, got 'maybe'"}));
  EXPECT_EQ(only_problem("run: 5\n"),
            (problem{"bad.yaml", 1, 6, "run", "expected a mapping, got '5'"}));
  EXPECT_EQ(only_problem("cameras: {id: 1}\n"),
            (problem{"bad.yaml", 1, 10, "cameras", "expected a list, got a mapping"}));
  EXPECT_EQ(only_problem("run: {speed: [1, 2]}\n"),
            (problem{"bad.yaml", 1, 14, "run.speed", "expected a number, got a list"}));
}

TEST(scenario_validation, bad_enum_names_the_choices) {
  EXPECT_EQ(
      only_problem("cameras:\n  - id: 1\n    position: [0, 0]\n    type: dome\n"),
      (problem{"bad.yaml", 4, 11, "cameras[0].type", "expected one of: static, ptz, got 'dome'"}));
  EXPECT_EQ(only_problem("controller: {solver: best_solve}\n"),
            (problem{"bad.yaml", 1, 22, "controller.solver",
                     "expected one of: best_solv, all_solv, optimistic_solv, bound_solv, got "
                     "'best_solve'; "
                     "did you mean "
                     "'best_solv'?"}));
  EXPECT_EQ(only_problem("world: {clothing: plain}\n"),
            (problem{"bad.yaml", 1, 19, "world.clothing",
                     "expected one of: palette, varied, got 'plain'"}));
  EXPECT_EQ(only_problem("network: {unicast: reverse}\n"),
            (problem{"bad.yaml", 1, 20, "network.unicast",
                     "expected one of: flood, reverse_path, got 'reverse'"}));
  EXPECT_EQ(only_problem("sensing: {tracker_scales: frame}\n"),
            (problem{"bad.yaml", 1, 27, "sensing.tracker_scales",
                     "expected one of: target, paper, got 'frame'"}));
}

TEST(scenario_validation, out_of_range_run_values) {
  EXPECT_EQ(only_problem("run: {tick: 2 s}\n"),
            (problem{"bad.yaml", 1, 13, "run.tick", "expected a duration in (0 s, 1 s], got 2 s"}));
  EXPECT_EQ(
      only_problem("run: {tick: 0 ms}\n"),
      (problem{"bad.yaml", 1, 13, "run.tick", "expected a duration in (0 s, 1 s], got 0 ms"}));
  EXPECT_EQ(only_problem("run: {duration: 0 s}\n"),
            (problem{"bad.yaml", 1, 17, "run.duration", "expected a duration > 0 s, got 0 s"}));
  EXPECT_EQ(only_problem("run: {speed: -1}\n"),
            (problem{"bad.yaml", 1, 14, "run.speed", "expected a number >= 0, got -1"}));
  EXPECT_EQ(
      only_problem("run: {threads: 300}\n"),
      (problem{"bad.yaml", 1, 16, "run.threads", "expected an integer in [0, 256], got 300"}));
}

TEST(scenario_validation, out_of_range_world_values) {
  EXPECT_EQ(only_problem("world: {population: 1000001}\n"),
            (problem{"bad.yaml", 1, 21, "world.population",
                     "expected an integer in [0, 1000000], got 1000001"}));
  EXPECT_EQ(only_problem("world: {partitions: 0}\n"),
            (problem{"bad.yaml", 1, 21, "world.partitions", "expected an integer >= 1, got 0"}));
}

TEST(scenario_validation, out_of_range_network_values) {
  EXPECT_EQ(only_problem("network: {loss_probability: 1.5}\n"),
            (problem{"bad.yaml", 1, 29, "network.loss_probability",
                     "expected a number in [0, 1], got 1.5"}));
  EXPECT_EQ(only_problem("network: {max_hops: 0}\n"),
            (problem{"bad.yaml", 1, 21, "network.max_hops", "expected an integer >= 1, got 0"}));
  EXPECT_EQ(only_problem("network: {min_delay: 300 ms, max_delay: 250 ms}\n"),
            (problem{"bad.yaml", 1, 41, "network.max_delay",
                     "expected a duration >= 300 ms (at least min_delay), got 250 ms"}));
  EXPECT_EQ(only_problem("network: {min_delay: 1 s}\n"),
            (problem{"bad.yaml", 1, 10, "network.max_delay",
                     "expected a duration >= 1 s (at least min_delay), got 500 ms (the default)"}));
  EXPECT_EQ(
      only_problem("network: {hello_interval: 0 s}\n"),
      (problem{"bad.yaml", 1, 27, "network.hello_interval", "expected a duration > 0 s, got 0 s"}));
  EXPECT_EQ(only_problem("network: {neighbour_timeout: -1 s}\n"),
            (problem{"bad.yaml", 1, 30, "network.neighbour_timeout",
                     "expected a duration > 1 s (longer than hello_interval), got -1 s"}));
  EXPECT_EQ(only_problem("network: {hello_interval: 2 s, neighbour_timeout: 2 s}\n"),
            (problem{"bad.yaml", 1, 51, "network.neighbour_timeout",
                     "expected a duration > 2 s (longer than hello_interval), got 2 s"}));
  EXPECT_EQ(only_problem("network: {hello_interval: 6 s}\n"),
            (problem{"bad.yaml", 1, 10, "network.neighbour_timeout",
                     "expected a duration > 6 s (longer than hello_interval), got 5 s (the "
                     "default)"}));
  // A bad hello_interval is reported alone; neighbour_timeout is then only checked positive.
  EXPECT_EQ(
      only_problem("network: {hello_interval: 0 s, neighbour_timeout: 1 s}\n"),
      (problem{"bad.yaml", 1, 27, "network.hello_interval", "expected a duration > 0 s, got 0 s"}));
}

TEST(scenario_validation, out_of_range_controller_values) {
  EXPECT_EQ(only_problem("controller: {wait_timeout: 0 s}\n"),
            (problem{"bad.yaml", 1, 28, "controller.wait_timeout",
                     "expected a duration > 0 s, got 0 s"}));
  EXPECT_EQ(only_problem("controller: {min_relevance: -0.1}\n"),
            (problem{"bad.yaml", 1, 29, "controller.min_relevance",
                     "expected a number in [0, 1], got -0.1"}));
  EXPECT_EQ(only_problem("controller: {relevance_sigma_pan_deg: 0}\n"),
            (problem{"bad.yaml", 1, 39, "controller.relevance_sigma_pan_deg",
                     "expected a number > 0, got 0"}));
}

TEST(scenario_validation, out_of_range_imaging_values) {
  const std::string camera = "cameras:\n  - id: 1\n    position: [0, 0]\n    imaging:\n";
  EXPECT_EQ(only_problem(camera + "      jpeg_quality: 101\n"),
            (problem{"bad.yaml", 5, 21, "cameras[0].imaging.jpeg_quality",
                     "expected an integer in [0, 100], got 101"}));
  EXPECT_EQ(only_problem(camera + "      resolution: [640, 8]\n"),
            (problem{"bad.yaml", 5, 25, "cameras[0].imaging.resolution[1]",
                     "expected an integer in [16, 8192], got 8"}));
  EXPECT_EQ(only_problem(camera + "      noise_sigma: -1\n"),
            (problem{"bad.yaml", 5, 20, "cameras[0].imaging.noise_sigma",
                     "expected a number >= 0, got -1"}));
  EXPECT_EQ(only_problem(camera + "      dropout: {fraction: 2}\n"),
            (problem{"bad.yaml", 5, 27, "cameras[0].imaging.dropout.fraction",
                     "expected a number in [0, 1], got 2"}));
}

TEST(scenario_validation, pose_outside_its_limits) {
  EXPECT_EQ(only_problem("cameras:\n  - id: 3\n    position: [0, 0]\n    field_of_view_deg: 200\n"),
            (problem{"bad.yaml", 4, 24, "cameras[0].field_of_view_deg",
                     "expected a number in [5, 90] (within field_of_view_limits), got 200"}));
}

TEST(scenario_validation, default_pose_outside_the_given_limits) {
  // tilt_deg defaults to -20, which [-10, 10] excludes; the problem points at the camera.
  EXPECT_EQ(
      only_problem("cameras:\n  - id: 1\n    position: [0, 0]\n    tilt_limits: [-10, 10]\n"),
      (problem{"bad.yaml", 2, 5, "cameras[0].tilt_deg",
               "expected a number in [-10, 10] (within tilt_limits), got -20 (the default)"}));
}

TEST(scenario_validation, limits_must_be_ordered_and_field_of_view_below_180) {
  EXPECT_EQ(only_problem("cameras:\n  - {id: 1, position: [0, 0], pan_limits: [90, -90]}\n"),
            (problem{"bad.yaml", 2, 43, "cameras[0].pan_limits",
                     "expected [min, max] with min <= max, got [90, -90]"}));
  EXPECT_EQ(
      only_problem("cameras:\n  - {id: 1, position: [0, 0], field_of_view_limits: [0, 90]}\n"),
      (problem{"bad.yaml", 2, 54, "cameras[0].field_of_view_limits[0]",
               "expected a number in (0, 180), got 0"}));
  EXPECT_EQ(only_problem("cameras:\n  - {id: 1, position: [0, 0], tilt_limits: [-80]}\n"),
            (problem{"bad.yaml", 2, 44, "cameras[0].tilt_limits",
                     "expected a list [min, max] of 2 numbers, got a list of 1"}));
}

TEST(scenario_validation, duplicate_camera_id_names_both_lines) {
  EXPECT_EQ(
      only_problem("cameras:\n  - id: 4\n    position: [0, 0]\n  - id: 4\n    position: [1, 1]\n"),
      (problem{"bad.yaml", 4, 9, "cameras[1].id", "duplicate camera id 4 (first used at line 2)"}));
}

TEST(scenario_validation, camera_id_must_be_positive) {
  EXPECT_EQ(only_problem("cameras:\n  - {id: 0, position: [0, 0]}\n"),
            (problem{"bad.yaml", 2, 10, "cameras[0].id", "expected an integer >= 1, got 0"}));
}

TEST(scenario_validation, missing_required_keys_point_at_the_parent_mapping) {
  EXPECT_EQ(only_problem("cameras:\n  - id: 1\n    height_m: 3\n"),
            (problem{"bad.yaml", 2, 5, "cameras[0].position", "missing required key 'position'"}));
  EXPECT_EQ(only_problem(one_camera + "tasks:\n  - {pedestrian: 2, camera: 1}\n"),
            (problem{"bad.yaml", 4, 5, "tasks[0].at", "missing required key 'at'"}));
  EXPECT_EQ(only_problem(one_camera + "tasks:\n  - {at: 1 s, pedestrian: 2}\n"),
            (problem{"bad.yaml", 4, 5, "tasks[0].camera", "missing required key 'camera'"}));
  EXPECT_EQ(only_problem(one_camera + "faults:\n  - {kind: crash, camera: 1}\n"),
            (problem{"bad.yaml", 4, 5, "faults[0].at", "missing required key 'at'"}));
  EXPECT_EQ(only_problem("cameras:\n  - {id: 1, position: {x_m: 3}}\n"),
            (problem{"bad.yaml", 2, 23, "cameras[0].position.y_m", "missing required key 'y_m'"}));
}

TEST(scenario_validation, link_faults_need_a_peer_and_timed_faults_a_length) {
  EXPECT_EQ(only_problem(one_camera + "faults:\n  - {at: 1 s, kind: link_cut, camera: 1}\n"),
            (problem{"bad.yaml", 4, 5, "faults[0].peer",
                     "missing required key 'peer' (needed by link_cut)"}));
  EXPECT_EQ(
      only_problem(one_camera + "faults:\n  - {at: 1 s, kind: crash_and_recover, camera: 1}\n"),
      (problem{"bad.yaml", 4, 5, "faults[0].length",
               "missing required key 'length' (needed by crash_and_recover)"}));
  EXPECT_EQ(only_problem(one_camera +
                         "faults:\n  - {at: 1 s, kind: loss_burst, camera: 1, length: 0 s}\n"),
            (problem{"bad.yaml", 4, 52, "faults[0].length", "expected a duration > 0 s, got 0 s"}));
  EXPECT_EQ(only_problem(one_camera + "faults:\n  - {at: -1 s, kind: crash, camera: 1}\n"),
            (problem{"bad.yaml", 4, 10, "faults[0].at", "expected a duration >= 0 s, got -1 s"}));
}

TEST(scenario_validation, references_must_name_existing_cameras) {
  EXPECT_EQ(only_problem(one_camera + "tasks:\n  - {at: 1 s, pedestrian: 1, camera: 7}\n"),
            (problem{"bad.yaml", 4, 38, "tasks[0].camera", "no camera has id 7 (camera ids: 1)"}));
  EXPECT_EQ(
      only_problem(one_camera + "faults:\n  - {at: 1 s, kind: link_cut, camera: 1, peer: 2}\n"),
      (problem{"bad.yaml", 4, 48, "faults[0].peer", "no camera has id 2 (camera ids: 1)"}));
  EXPECT_EQ(only_problem(one_camera + "network: {adjacency: [[1, 5]]}\n"),
            (problem{"bad.yaml", 3, 27, "network.adjacency[0][1]",
                     "no camera has id 5 (camera ids: 1)"}));
  EXPECT_EQ(only_problem(one_camera + "network: {adjacency: [[1, 1]]}\n"),
            (problem{"bad.yaml", 3, 27, "network.adjacency[0][1]",
                     "camera 1 cannot be its own neighbour"}));
}

TEST(scenario_validation, task_values_in_range) {
  EXPECT_EQ(
      only_problem(one_camera + "tasks:\n  - {at: 1 s, pedestrian: -1, camera: 1}\n"),
      (problem{"bad.yaml", 4, 27, "tasks[0].pedestrian", "expected an integer >= 1, got -1"}));
  EXPECT_EQ(
      only_problem(one_camera +
                   "tasks:\n  - {at: 1 s, pedestrian: 1, camera: 1, cameras_wanted: 0}\n"),
      (problem{"bad.yaml", 4, 57, "tasks[0].cameras_wanted", "expected an integer >= 1, got 0"}));
}

TEST(scenario_validation, a_task_names_its_target_one_way) {
  EXPECT_EQ(only_problem(one_camera + "tasks:\n  - {at: 1 s, camera: 1}\n"),
            (problem{"bad.yaml", 4, 5, "tasks[0].pedestrian",
                     "expected one of pedestrian (an id), pixel ([x, y] in the camera's frame) "
                     "or first_to_enter (a camera id)"}));
  EXPECT_EQ(only_problem(one_camera + "tasks:\n  - {at: 1 s, camera: 1, pedestrian: 3, "
                                      "pixel: [1, 2]}\n"),
            (problem{"bad.yaml", 4, 5, "tasks[0].pedestrian",
                     "expected only one of pedestrian, pixel and first_to_enter, got pedestrian "
                     "and pixel"}));
  EXPECT_EQ(
      only_problem(one_camera + "tasks:\n  - {at: 1 s, camera: 1, pixel: [640, 2]}\n"),
      (problem{"bad.yaml", 4, 34, "tasks[0].pixel[0]", "expected a number in [0, 640), got 640"}));
  EXPECT_EQ(only_problem(one_camera + "tasks:\n  - {at: 1 s, camera: 1, pixel: 5}\n"),
            (problem{"bad.yaml", 4, 33, "tasks[0].pixel",
                     "expected [x, y], a pixel in the camera's frame"}));
  EXPECT_EQ(only_problem(one_camera + "tasks:\n  - {at: 1 s, first_to_enter: 3}\n"),
            (problem{"bad.yaml", 4, 31, "tasks[0].first_to_enter",
                     "no camera has id 3 (camera ids: 1)"}));
  EXPECT_EQ(
      only_problem(one_camera +
                   "tasks:\n  - {at: 9 s, pedestrian: 2, camera: 1, cancel_at: 9 s}\n"),
      (problem{"bad.yaml", 4, 52, "tasks[0].cancel_at", "expected a duration > 9 s, got 9 s"}));
}

TEST(scenario_validation, several_problems_are_reported_together_in_file_order) {
  const auto file = data_dir / "several_problems.yaml";
  try {
    load_scenario(file);
    FAIL() << "no scenario_error";
  } catch (const scenario_error& error) {
    const auto name = file.string();
    const std::vector<problem> expected{
        {name, 2, 9, "run.tick", "expected a duration in (0 s, 1 s], got 2 s"},
        {name, 6, 11, "cameras[0].type", "expected one of: static, ptz, got 'dome'"},
        {name, 7, 9, "cameras[1].id", "duplicate camera id 1 (first used at line 4)"},
        {name, 10, 5, "tasks[0].camera", "missing required key 'camera'"},
    };
    EXPECT_EQ(error.problems(), expected);
    EXPECT_EQ(std::string{error.what()},
              name + ":2:9: run.tick: expected a duration in (0 s, 1 s], got 2 s\n" + name +
                  ":6:11: cameras[0].type: expected one of: static, ptz, got 'dome'\n" + name +
                  ":7:9: cameras[1].id: duplicate camera id 1 (first used at line 4)\n" + name +
                  ":10:5: tasks[0].camera: missing required key 'camera'");
  }
}

TEST(scenario_validation, an_empty_name_is_rejected) {
  EXPECT_EQ(only_problem("name: ''\n"),
            (problem{"bad.yaml", 1, 7, "name", "expected a non-empty name"}));
}

TEST(scenario_validation, a_document_that_is_not_a_mapping) {
  EXPECT_EQ(only_problem("- 1\n- 2\n"),
            (problem{"bad.yaml", 1, 1, "", "expected a mapping, got a list"}));
}

}  // namespace
}  // namespace argus::config
