#include "config/scenario_loader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

namespace argus::config {

/// Lets GoogleTest print a problem as the user would see it.
inline void PrintTo(const problem& what, std::ostream* out) {
  *out << to_string(what);
}

namespace {

using namespace std::chrono_literals;

const std::filesystem::path data_dir{ARGUS_CONFIG_TEST_DATA_DIR};

/// The problems `parse` throws, or none if it succeeds.
template <class Parse>
std::vector<problem> problems_of(Parse parse) {
  try {
    parse();
  } catch (const scenario_error& error) {
    return error.problems();
  }
  return {};
}

// Table 2 of the paper, network communication parameters: one assertion per parameter.
TEST(scenario_loader, network_defaults_are_table_2) {
  const auto loaded = parse_scenario("name: defaults\n", "defaults.yaml");
  const auto& network = loaded.network;
  EXPECT_EQ(network.loss_probability, 0.1);
  EXPECT_EQ(network.min_delay, 200ms);
  EXPECT_EQ(network.max_delay, 500ms);
  EXPECT_EQ(network.node_failure_probability, 0.001);
  EXPECT_EQ(network.max_hops, 3u);
  EXPECT_EQ(network.message_timeout, 1500ms);
  // Not in Table 2: the hello beacon's period and the silence after which a neighbour is
  // given up (the values of the heartbeat and member failure timeout they used to borrow).
  EXPECT_EQ(network.hello_interval, 1s);
  EXPECT_EQ(network.neighbour_timeout, 5s);
  EXPECT_EQ(network.unicast, unicast_routing::flood);  // every message multi-hop is flooded
}

// Table 2, controller and at-node parameters, and the eq. (1) spreads.
TEST(scenario_loader, controller_defaults_are_table_2) {
  const auto loaded = parse_scenario("name: defaults\n", "defaults.yaml");
  const auto& controller = loaded.controller;
  EXPECT_EQ(controller.wait_timeout, 2min);
  EXPECT_EQ(controller.search_timeout, 5min);
  EXPECT_EQ(controller.min_relevance, 0.1);
  EXPECT_EQ(controller.heartbeat_interval, 1000ms);
  EXPECT_EQ(controller.leader_failure_timeout, 3000ms);
  EXPECT_EQ(controller.member_failure_timeout, 5000ms);
  EXPECT_EQ(controller.auction_relevance_threshold, 0.5);
  EXPECT_EQ(controller.min_task_duration, 1min);
  EXPECT_EQ(controller.membership_relevance_threshold, 0.1);
  EXPECT_EQ(controller.merge_timeout, 5min);
  EXPECT_EQ(controller.bidding_timeout, 2min);
  EXPECT_EQ(controller.relevance_sigma_fov_deg, 5.0);
  EXPECT_EQ(controller.relevance_sigma_pan_deg, 5.0);
  EXPECT_EQ(controller.relevance_sigma_tilt_deg, 5.0);
  EXPECT_EQ(controller.solver, conflict_solver::optimistic_solv);
}

TEST(scenario_loader, fills_defaults_and_names_the_scenario_after_the_file) {
  const auto loaded = parse_scenario("", "scenarios/empty_room.yaml");
  EXPECT_EQ(loaded.name, "empty_room");
  EXPECT_EQ(loaded.source_path, "scenarios/empty_room.yaml");
  EXPECT_EQ(loaded.run, run_settings{});
  EXPECT_TRUE(loaded.run.output_dir.empty());
  EXPECT_EQ(loaded.world, world_settings{});
  EXPECT_EQ(loaded.network, network_settings{});
  EXPECT_EQ(loaded.controller, controller_settings{});
  EXPECT_TRUE(loaded.cameras.empty());
  EXPECT_TRUE(loaded.tasks.empty());
  EXPECT_TRUE(loaded.faults.empty());
}

TEST(scenario_loader, empty_sections_keep_their_defaults) {
  const auto loaded = parse_scenario("run:\nworld:\nnetwork: {}\ncameras:\n", "x.yaml");
  EXPECT_EQ(loaded.run, run_settings{});
  EXPECT_EQ(loaded.world, world_settings{});
  EXPECT_EQ(loaded.network, network_settings{});
  EXPECT_TRUE(loaded.cameras.empty());
}

TEST(scenario_loader, reads_every_field_of_a_full_scenario) {
  const auto file = data_dir / "full.yaml";
  const auto loaded = load_scenario(file);
  EXPECT_EQ(loaded.name, "full_demo");
  EXPECT_EQ(loaded.source_path, file.string());

  EXPECT_EQ(loaded.run.seed, 7u);
  EXPECT_EQ(loaded.run.duration, 2min);
  EXPECT_EQ(loaded.run.tick, seconds{1.0 / 30.0});
  EXPECT_EQ(loaded.run.speed, 2.5);
  EXPECT_EQ(loaded.run.threads, 2u);
  EXPECT_EQ(loaded.run.output_dir, "out/demo");

  EXPECT_EQ(loaded.world.layout, "stations/x.yaml");
  EXPECT_EQ(loaded.world.population, 250u);
  EXPECT_EQ(loaded.world.spawn_rate_per_min, 45.0);
  EXPECT_EQ(loaded.world.partitions, 4u);
  EXPECT_EQ(loaded.world.clothes, clothing::varied);

  ASSERT_EQ(loaded.cameras.size(), 3u);
  const auto& first = loaded.cameras[0];
  EXPECT_EQ(first.id, 1);
  EXPECT_EQ(first.position, (plan_point{10.0, 20.0}));
  EXPECT_EQ(first.height_m, 5.5);
  EXPECT_EQ(first.type, camera_type::static_camera);
  EXPECT_EQ(first.pan_deg, 30.0);
  EXPECT_EQ(first.tilt_deg, -30.0);
  EXPECT_EQ(first.field_of_view_deg, 60.0);
  EXPECT_EQ(first.pan_limits, (degree_range{-90.0, 90.0}));
  EXPECT_EQ(first.tilt_limits, (degree_range{-60.0, 0.0}));
  EXPECT_EQ(first.field_of_view_limits, (degree_range{10.0, 80.0}));
  EXPECT_EQ(first.pan_rate_deg_per_s, 45.0);
  EXPECT_EQ(first.tilt_rate_deg_per_s, 25.0);
  EXPECT_EQ(first.zoom_rate_deg_per_s, 15.0);
  const auto& imaging = first.imaging;
  EXPECT_EQ(imaging.width_px, 320u);
  EXPECT_EQ(imaging.height_px, 240u);
  EXPECT_TRUE(imaging.color_response_enabled);
  EXPECT_EQ(imaging.response, (color_response{10.0, 0.9, 1.1, 0.05, 0.2, 0.3, 0.1}));
  EXPECT_EQ(imaging.noise_sigma, 4.0);
  EXPECT_EQ(imaging.dropout_fraction, 0.01);
  EXPECT_EQ(imaging.dropout, dropout_kind::salt_and_pepper);
  EXPECT_EQ(imaging.jpeg_quality, 75u);
  EXPECT_TRUE(imaging.interlace);

  EXPECT_EQ(loaded.cameras[1].position, (plan_point{30.5, -4.0}));  // list form
  EXPECT_EQ(loaded.cameras[1].type, camera_type::ptz);
  EXPECT_FALSE(loaded.cameras[2].imaging.color_response_enabled);
  EXPECT_EQ(loaded.cameras[2].imaging.dropout, dropout_kind::bit_flip);

  const auto& network = loaded.network;
  EXPECT_EQ(network.loss_probability, 0.2);
  EXPECT_EQ(network.min_delay, 100ms);
  EXPECT_EQ(network.max_delay, 750ms);
  EXPECT_EQ(network.node_failure_probability, 0.01);
  EXPECT_EQ(network.max_hops, 5u);
  EXPECT_EQ(network.message_timeout, 2s);
  EXPECT_EQ(network.communication_range_m, 25.0);
  EXPECT_EQ(network.adjacency, (std::vector<std::array<int, 2>>{{1, 2}, {2, 3}}));
  EXPECT_EQ(network.duplicate_probability, 0.05);
  EXPECT_TRUE(network.reorder);
  EXPECT_EQ(network.hello_interval, 750ms);
  EXPECT_EQ(network.neighbour_timeout, 4s);
  EXPECT_EQ(network.unicast, unicast_routing::reverse_path);

  const auto& controller = loaded.controller;
  EXPECT_EQ(controller.wait_timeout, 90s);
  EXPECT_EQ(controller.search_timeout, 4min);
  EXPECT_EQ(controller.min_relevance, 0.2);
  EXPECT_EQ(controller.heartbeat_interval, 500ms);
  EXPECT_EQ(controller.leader_failure_timeout, 2500ms);
  EXPECT_EQ(controller.member_failure_timeout, 6s);
  EXPECT_EQ(controller.auction_relevance_threshold, 0.6);
  EXPECT_EQ(controller.min_task_duration, 30s);
  EXPECT_EQ(controller.membership_relevance_threshold, 0.15);
  EXPECT_EQ(controller.merge_timeout, 3min);
  EXPECT_EQ(controller.bidding_timeout, 1min);
  EXPECT_EQ(controller.relevance_sigma_fov_deg, 4.0);
  EXPECT_EQ(controller.relevance_sigma_pan_deg, 6.0);
  EXPECT_EQ(controller.relevance_sigma_tilt_deg, 7.0);
  EXPECT_EQ(controller.solver, conflict_solver::all_solv);

  ASSERT_EQ(loaded.tasks.size(), 1u);
  EXPECT_EQ(loaded.tasks[0].at, 10s);
  EXPECT_EQ(loaded.tasks[0].pedestrian, 12);
  EXPECT_EQ(loaded.tasks[0].camera, 2);
  EXPECT_EQ(loaded.tasks[0].cameras_wanted, 2u);

  ASSERT_EQ(loaded.faults.size(), 6u);
  EXPECT_EQ(loaded.faults[0].kind, fault_kind::crash);
  EXPECT_EQ(loaded.faults[0].peer, std::nullopt);
  EXPECT_EQ(loaded.faults[1].kind, fault_kind::crash_and_recover);
  EXPECT_EQ(loaded.faults[1].length, 30s);
  EXPECT_EQ(loaded.faults[2].kind, fault_kind::link_cut);
  EXPECT_EQ(loaded.faults[2].peer, 2);
  EXPECT_EQ(loaded.faults[3].kind, fault_kind::link_heal);
  EXPECT_EQ(loaded.faults[4].kind, fault_kind::loss_burst);
  EXPECT_EQ(loaded.faults[4].at, 120s);
  EXPECT_EQ(loaded.faults[4].camera, 2);
  EXPECT_EQ(loaded.faults[4].length, 5s);
  EXPECT_EQ(loaded.faults[4].loss_probability, 0.8);
  EXPECT_EQ(loaded.faults[5].kind, fault_kind::delay_spike);
  EXPECT_EQ(loaded.faults[5].length, 4s);
  EXPECT_EQ(loaded.faults[5].delay, 1500ms);
}

TEST(scenario_loader, a_delay_spike_needs_its_delay) {
  const std::string cameras = "cameras:\n  - {id: 1, position: [0, 0]}\n";
  try {
    parse_scenario(cameras + "faults:\n  - {at: 1 s, kind: delay_spike, camera: 1, length: 2 s}\n",
                   "x.yaml");
    FAIL() << "a delay_spike without its delay was taken";
  } catch (const scenario_error& e) {
    EXPECT_NE(std::string(e.what()).find("faults[0].delay"), std::string::npos) << e.what();
  }
}

TEST(scenario_loader, color_response_on_enables_the_default_response) {
  const auto loaded = parse_scenario(
      "cameras:\n  - {id: 1, position: [0, 0], imaging: {color_response: on}}\n", "x.yaml");
  EXPECT_TRUE(loaded.cameras[0].imaging.color_response_enabled);
  EXPECT_EQ(loaded.cameras[0].imaging.response, color_response{});
}

TEST(scenario_loader, reads_every_conflict_solver) {
  EXPECT_EQ(parse_scenario("controller: {solver: all_solv}\n", "x.yaml").controller.solver,
            conflict_solver::all_solv);
  EXPECT_EQ(parse_scenario("controller: {solver: best_solv}\n", "x.yaml").controller.solver,
            conflict_solver::best_solv);
  EXPECT_EQ(parse_scenario("controller: {solver: bound_solv}\n", "x.yaml").controller.solver,
            conflict_solver::bound_solv);
}

TEST(scenario_loader, reads_speeds_flows_and_measurement_areas) {
  const auto loaded = parse_scenario(R"(world:
  speed: {mean_mps: 1.2, sd_mps: 0.1, min_mps: 0.8, max_mps: 1.6}
  flows:
    - {name: in, min: [1, 2], max: [3, 4], count: 20, rate_per_s: 2, start: 5 s, exit: east}
  measurement_areas:
    - {name: middle, min: [9, 1], max: [13, 5]}
)",
                                     "flows.yaml");
  EXPECT_EQ(loaded.world.speed, (speed_settings{1.2, 0.1, 0.8, 1.6}));
  ASSERT_EQ(loaded.world.flows.size(), 1u);
  const auto& flow = loaded.world.flows[0];
  EXPECT_EQ(flow.name, "in");
  EXPECT_EQ(flow.spawn, (plan_box{1, 2, 3, 4}));
  EXPECT_EQ(flow.count, 20u);
  EXPECT_EQ(flow.rate_per_s, 2.0);
  EXPECT_EQ(flow.start, seconds{5.0});
  EXPECT_EQ(flow.exit, "east");
  ASSERT_EQ(loaded.world.measurement_areas.size(), 1u);
  EXPECT_EQ(loaded.world.measurement_areas[0].area, (plan_box{9, 1, 13, 5}));
  // The defaults are Weidmann's.
  EXPECT_EQ(parse_scenario("", "x.yaml").world.speed, (speed_settings{1.34, 0.26, 0.6, 2.0}));
}

TEST(scenario_loader, a_flow_needs_a_count_an_exit_and_a_proper_box) {
  try {
    parse_scenario(R"(world:
  speed: {mean_mps: 2.5, max_mps: 2.0}
  flows:
    - {name: in, min: [3, 2], max: [1, 4]}
)",
                   "flows.yaml");
    FAIL() << "accepted";
  } catch (const scenario_error& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("world.speed: expected min_mps <= mean_mps <= max_mps"), std::string::npos)
        << text;
    EXPECT_NE(text.find("world.flows[0].max: expected max > min"), std::string::npos) << text;
    EXPECT_NE(text.find("world.flows[0].count"), std::string::npos) << text;
    EXPECT_NE(text.find("world.flows[0].exit"), std::string::npos) << text;
  }
}

TEST(scenario_loader, loads_the_minimal_scenario) {
  const auto loaded =
      load_scenario(std::filesystem::path{ARGUS_SOURCE_DIR} / "scenarios" / "minimal.yaml");
  EXPECT_EQ(loaded.name, "minimal");
  EXPECT_EQ(loaded.run.duration, 20s);
  ASSERT_EQ(loaded.cameras.size(), 4u);
  for (const auto& camera : loaded.cameras) {
    // Around a 40 m x 30 m room.
    EXPECT_GE(camera.position.x_m, 0.0);
    EXPECT_LE(camera.position.x_m, 40.0);
    EXPECT_GE(camera.position.y_m, 0.0);
    EXPECT_LE(camera.position.y_m, 30.0);
  }
  EXPECT_EQ(loaded.tasks.size(), 1u);
  EXPECT_EQ(loaded.faults.size(), 1u);
}

TEST(scenario_loader, a_missing_file_names_the_file_and_the_reason) {
  const auto file = data_dir / "no_such_file.yaml";
  const auto problems = problems_of([&] { load_scenario(file); });
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0],
            (problem{file.string(), 0, 0, "", "cannot open file: No such file or directory"}));
}

TEST(scenario_loader, a_directory_cannot_be_opened_as_a_file) {
  const auto problems = problems_of([&] { load_scenario(data_dir); });
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0],
            (problem{data_dir.string(), 0, 0, "", "cannot open file: Is a directory"}));
}

TEST(scenario_loader, a_yaml_syntax_error_gives_file_line_column_and_yaml_cpp_message) {
  const auto file = data_dir / "syntax_error.yaml";
  const auto problems = problems_of([&] { load_scenario(file); });
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0], (problem{file.string(), 2, 6, "", "end of map flow not found"}));
}

TEST(scenario_loader, rejects_a_second_document) {
  const auto problems = problems_of([] { parse_scenario("name: a\n---\nname: b\n", "two.yaml"); });
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0], (problem{"two.yaml", 3, 1, "", "expected one YAML document, got 2"}));
}

// yaml-cpp 0.7 never finishes reading a ',' outside a flow collection (jbeder/yaml-cpp#1040):
// LoadAll yields empty documents until memory runs out. Found by tests/fuzz/scenario_yaml.
bool stray_commas_are_syntax_errors() {
  const auto alone = problems_of([] { parse_scenario(",", "comma.yaml"); });
  const auto after_a_list = problems_of([] { parse_scenario("- 1\n,\n", "comma.yaml"); });
  // Field by field: comparing with braced temporaries trips g++ 12's -Wmaybe-uninitialized
  // at -O1 (the ASan build's).
  const auto is = [](const std::vector<problem>& p, int line) {
    return p.size() == 1 && p[0].file == "comma.yaml" && p[0].line == line && p[0].column == 1 &&
           p[0].field.empty() && p[0].message == "unexpected ','";
  };
  return is(alone, 1) && is(after_a_list, 2);
}

// In a child process with an alarm, so that a regression fails in seconds instead of filling
// memory.
TEST(scenario_loader, a_stray_comma_is_a_syntax_error_not_a_hang) {
  EXPECT_EXIT(
      {
        alarm(20);
        std::exit(stray_commas_are_syntax_errors() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

// yaml-cpp reads a NUL as an escape even outside quotes: "pe NUL _x" gave the name "pe", a lone
// 0xA0 byte and "x", which is not UTF-8, so that to_yaml's file of it no longer loaded. Found by
// tests/fuzz/scenario_yaml.
TEST(scenario_loader, a_nul_byte_is_refused_with_its_place) {
  const auto problems = problems_of(
      [] { parse_scenario(std::string("run: {seed: 1}\nname: pe\0_x\n", 27), "nul.yaml"); });
  EXPECT_EQ(problems, (std::vector{problem{"nul.yaml", 2, 9, "",
                                           "unexpected NUL byte (YAML allows none in a file)"}}));
}

// The pixel trackers' kernel sizes: around the target by default, the paper's on request.
TEST(scenario_loader, trackers_know_no_poses_and_cameras_zoom_in_track_unless_told) {
  const auto paper = parse_scenario("name: a\n", "a.yaml");
  EXPECT_FALSE(paper.sensing.ego_motion);
  EXPECT_TRUE(paper.controller.zoom_in_track);
  EXPECT_FALSE(paper.controller.track_while_bidding);
  EXPECT_FALSE(paper.controller.share_model);
  const auto ours = parse_scenario(
      "sensing: {ego_motion: true}\ncontroller: {zoom_in_track: false, track_while_bidding: "
      "true, share_model: true}\n",
      "a.yaml");
  EXPECT_TRUE(ours.sensing.ego_motion);
  EXPECT_FALSE(ours.controller.zoom_in_track);
  EXPECT_TRUE(ours.controller.track_while_bidding);
  EXPECT_TRUE(ours.controller.share_model);
}

// The oracle's instruments: the oracle as first built unless told; a bad name is refused.
TEST(scenario_loader, the_oracle_takes_its_own_views_and_zooms_unless_told) {
  const auto first = parse_scenario("name: a\n", "a.yaml");
  EXPECT_EQ(first.controller.oracle_signature_from, oracle_signature::own_view);
  EXPECT_TRUE(first.controller.oracle_zoom);
  const auto told = parse_scenario(
      "controller: {strategy: oracle, oracle_signature: operator, oracle_zoom: false}\n", "a.yaml");
  EXPECT_EQ(told.controller.oracle_signature_from, oracle_signature::operator_pick);
  EXPECT_FALSE(told.controller.oracle_zoom);
  const auto problems =
      problems_of([] { parse_scenario("controller: {oracle_signature: pick}\n", "b.yaml"); });
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].field, "controller.oracle_signature");
}

// What a node knows of the other cameras' views: nothing, the paper's, unless told.
TEST(scenario_loader, nodes_know_nothing_of_each_others_views_unless_told) {
  EXPECT_EQ(parse_scenario("name: a\n", "a.yaml").sensing.geometry, group_geometry::none);
  EXPECT_EQ(parse_scenario("sensing: {group_geometry: ground_truth}\n", "a.yaml").sensing.geometry,
            group_geometry::ground_truth);
  EXPECT_EQ(parse_scenario("sensing: {group_geometry: calibrated}\n", "a.yaml").sensing.geometry,
            group_geometry::calibrated);
  const auto problems =
      problems_of([] { parse_scenario("sensing: {group_geometry: learned}\n", "b.yaml"); });
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].field, "sensing.group_geometry");
  EXPECT_EQ(parse_scenario("name: a\n", "a.yaml").sensing.reappearance, reappearance_model::none);
  EXPECT_EQ(
      parse_scenario("sensing: {reappearance: ground_truth}\n", "a.yaml").sensing.reappearance,
      reappearance_model::ground_truth);
}

// The pixel trackers' reacquisition and model: the paper's unless told.
TEST(scenario_loader, trackers_keep_their_signature_and_search_the_whole_frame_unless_told) {
  const auto paper = parse_scenario("name: a\n", "a.yaml");
  EXPECT_FALSE(paper.sensing.signature_update);
  EXPECT_EQ(paper.sensing.reacquire_margin, 0.0);
  EXPECT_EQ(paper.sensing.local_search_frames, 0);
  EXPECT_EQ(paper.sensing.max_surround_match, 1.0);
  EXPECT_EQ(paper.sensing.surround_grace_frames, 0);
  EXPECT_EQ(paper.sensing.surround_grace_height_px, 0);
  EXPECT_EQ(paper.sensing.surround_patience_frames, 1);
  EXPECT_EQ(paper.sensing.surround_sides, 0);
  EXPECT_EQ(paper.sensing.track_rho, 0.4);
  EXPECT_EQ(paper.sensing.halves_rho, 0.0);
  EXPECT_EQ(paper.sensing.identity, config::identity_source::appearance);
  EXPECT_EQ(paper.controller.bid_evidence_time, config::seconds{0.0});
  const auto ours = parse_scenario(
      "sensing: {signature_update: true, reacquire_margin: 0.05, local_search_frames: 30,\n"
      "          max_surround_match: 0.65, surround_grace_frames: 15,\n"
      "          surround_grace_height_px: 40, surround_patience_frames: 2,\n"
      "          surround_sides: 3,\n"
      "          track_rho: 0.3, halves_rho: 0.45,\n"
      "          identity: ground_truth}\n"
      "controller: {bid_evidence_time: 1 s, bid_min_found_fraction: 0.6,\n"
      "             bid_min_mean_score: 0.5}\n",
      "a.yaml");
  EXPECT_EQ(ours.sensing.max_surround_match, 0.65);
  EXPECT_EQ(ours.sensing.surround_grace_frames, 15);
  EXPECT_EQ(ours.sensing.surround_grace_height_px, 40);
  EXPECT_EQ(ours.sensing.surround_patience_frames, 2);
  EXPECT_EQ(ours.sensing.surround_sides, 3);
  EXPECT_EQ(ours.sensing.track_rho, 0.3);
  EXPECT_EQ(ours.sensing.halves_rho, 0.45);
  EXPECT_EQ(ours.sensing.identity, config::identity_source::ground_truth);
  EXPECT_EQ(ours.controller.bid_evidence_time, config::seconds{1.0});
  EXPECT_EQ(ours.controller.bid_min_found_fraction, 0.6);
  EXPECT_EQ(ours.controller.bid_min_mean_score, 0.5);
  EXPECT_FALSE(problems_of([] {
                 parse_scenario("sensing: {max_surround_match: 1.5}\n", "a.yaml");
               }).empty());
  EXPECT_FALSE(problems_of([] {
                 parse_scenario("sensing: {surround_grace_frames: -1}\n", "a.yaml");
               }).empty());
  EXPECT_FALSE(problems_of([] {
                 parse_scenario("sensing: {surround_grace_height_px: -1}\n", "a.yaml");
               }).empty());
  EXPECT_FALSE(problems_of([] {
                 parse_scenario("sensing: {surround_patience_frames: 0}\n", "a.yaml");
               }).empty());
  EXPECT_FALSE(
      problems_of([] { parse_scenario("sensing: {surround_sides: 5}\n", "a.yaml"); }).empty());
  EXPECT_FALSE(
      problems_of([] { parse_scenario("sensing: {track_rho: 1.2}\n", "a.yaml"); }).empty());
  EXPECT_FALSE(
      problems_of([] { parse_scenario("sensing: {halves_rho: -0.1}\n", "a.yaml"); }).empty());
  EXPECT_FALSE(
      problems_of([] { parse_scenario("sensing: {identity: truth}\n", "a.yaml"); }).empty());
  EXPECT_FALSE(problems_of([] {
                 parse_scenario("controller: {bid_evidence_time: -1 s}\n", "a.yaml");
               }).empty());
  EXPECT_FALSE(problems_of([] {
                 parse_scenario("controller: {bid_min_mean_score: 2}\n", "a.yaml");
               }).empty());
  EXPECT_TRUE(ours.sensing.signature_update);
  EXPECT_EQ(ours.sensing.reacquire_margin, 0.05);
  EXPECT_EQ(ours.sensing.local_search_frames, 30);
  EXPECT_FALSE(
      problems_of([] { parse_scenario("sensing: {reacquire_margin: 1.5}\n", "a.yaml"); }).empty());
  EXPECT_FALSE(problems_of([] {
                 parse_scenario("sensing: {local_search_frames: -1}\n", "a.yaml");
               }).empty());
}

TEST(scenario_loader, tracker_scales_default_to_the_target_and_read_paper) {
  EXPECT_EQ(parse_scenario("name: a\n", "a.yaml").sensing.scales, tracker_scales::target);
  EXPECT_EQ(parse_scenario("sensing: {tracker_scales: paper}\n", "a.yaml").sensing.scales,
            tracker_scales::paper);
}

}  // namespace
}  // namespace argus::config
