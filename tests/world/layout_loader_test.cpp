// Layout files: the shipped Penn Station loads; bad files fail with file, line, field and
// what was expected.
#include "world/layout_loader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>

#include "config/scenario_loader.hpp"

namespace argus::world {
namespace {

std::vector<config::problem> problems_of(const std::string& text) {
  try {
    parse_layout(text, "bad.yaml");
  } catch (const config::scenario_error& error) {
    return error.problems();
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return {};
}

constexpr const char* minimal = R"(
size_m: [20, 10]
regions: [{name: hall, kind: waiting_room, min: [0, 0], max: [20, 10]}]
portals: [{name: door, kind: street, min: [0, 4], max: [1, 6]}]
)";

TEST(layout_loader, loads_the_builtin_penn_station) {
  const auto plan = load_layout(builtin_layout_path());
  EXPECT_EQ(plan.name, "penn_station");
  EXPECT_EQ(plan.size_m, vec2(200, 100));
  EXPECT_EQ(plan.ticket_booths.size(), 4u);
  EXPECT_EQ(plan.vending_machines.size(), 6u);
  EXPECT_EQ(plan.benches.size(), 12u);
  EXPECT_EQ(plan.stairways.size(), 6u);
  EXPECT_GE(plan.portals.size(), 8u);
  EXPECT_EQ(plan.regions.size(), 4u);
}

TEST(layout_loader, penn_station_scenario_validates_and_finds_its_layout) {
  const auto scenario = config::load_scenario(std::filesystem::path{ARGUS_SOURCE_DIR} /
                                              "scenarios" / "penn_station.yaml");
  EXPECT_EQ(scenario.cameras.size(), 16u);
  EXPECT_EQ(std::filesystem::weakly_canonical(layout_path(scenario)),
            std::filesystem::weakly_canonical(builtin_layout_path()));
  config::scenario empty;
  EXPECT_EQ(layout_path(empty), builtin_layout_path());
}

TEST(layout_loader, minimal_layout_loads) {
  const auto plan = parse_layout(minimal, "ok.yaml");
  EXPECT_EQ(plan.name, "ok");
  ASSERT_EQ(plan.portals.size(), 1u);
  EXPECT_EQ(plan.portals[0].kind, portal_kind::street);
}

TEST(layout_loader, portals_are_bounded_by_the_plans_own_size) {
  // Larger than the default 200 x 100: a portal near the far corner is inside the plan.
  const auto plan = parse_layout(R"(
size_m: [400, 300]
regions: [{name: hall, kind: waiting_room, min: [0, 0], max: [400, 300]}]
portals: [{name: door, kind: street, min: [390, 280], max: [400, 290]}]
)",
                                 "big.yaml");
  ASSERT_EQ(plan.portals.size(), 1u);
  EXPECT_EQ(plan.portals[0].area.max.y(), 290.0);
  // And one outside a smaller plan is refused.
  const auto problems = problems_of(R"(
size_m: [20, 10]
regions: [{name: hall, kind: waiting_room, min: [0, 0], max: [20, 10]}]
portals: [{name: door, kind: street, min: [0, 40], max: [1, 60]}]
)");
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems[0].message.find("the plan's height"), std::string::npos);
}

TEST(layout_loader, unknown_key_names_line_and_field) {
  const auto problems = problems_of(std::string{minimal} + "benchs: []\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].file, "bad.yaml");
  EXPECT_EQ(problems[0].line, 5);
  EXPECT_EQ(problems[0].field, "benchs");
  EXPECT_NE(problems[0].message.find("did you mean 'benches'"), std::string::npos);
}

TEST(layout_loader, bad_values_are_all_reported) {
  const auto problems = problems_of(R"(size_m: [20, 10]
regions:
  - {name: hall, kind: ballroom, min: [0, 0], max: [20, 10]}
portals:
  - {name: door, kind: street, min: [5, 4], max: [1, 6]}
benches:
  - {name: b, from: [2, 2], to: [3, 2], seats: 4}
stairs:
  - {min: [1, 1], max: [2, 30]}
)");
  ASSERT_EQ(problems.size(), 5u);
  EXPECT_EQ(problems[0].field, "regions[0].kind");
  EXPECT_EQ(problems[0].line, 3);
  EXPECT_EQ(problems[1].field, "portals[0].max");
  EXPECT_NE(problems[1].message.find("expected max > min"), std::string::npos);
  EXPECT_EQ(problems[2].field, "benches[0].to");
  EXPECT_EQ(problems[3].field, "stairs[0].name");
  EXPECT_NE(problems[3].message.find("missing required key"), std::string::npos);
  EXPECT_EQ(problems[4].field, "stairs[0].max[1]");
  EXPECT_EQ(problems[4].line, 9);
}

TEST(layout_loader, points_and_duplicates) {
  const auto problems = problems_of(R"(size_m: [20, 10]
regions: [{name: hall, kind: waiting_room, min: [0, 0], max: [20, 10]}]
portals: [{name: hall, kind: street, min: [0, 4], max: [1, 6]}]
walls: [[[0, 0]], [[1, x], [2, 2]]]
)");
  ASSERT_EQ(problems.size(), 3u);
  // Portals are read first, so the region is the duplicate.
  EXPECT_EQ(problems[0].field, "regions[0].name");
  EXPECT_NE(problems[0].message.find("duplicate name 'hall'"), std::string::npos);
  EXPECT_EQ(problems[1].field, "walls[0]");
  EXPECT_EQ(problems[2].field, "walls[1][0][1]");
}

TEST(layout_loader, no_entrance_and_missing_file) {
  const auto problems =
      problems_of(R"(regions: [{name: hall, kind: arcade, min: [0, 0], max: [20, 10]}]
)");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("street portal or stairs"), std::string::npos);
  try {
    load_layout("/nonexistent/layout.yaml");
    FAIL();
  } catch (const config::scenario_error& error) {
    EXPECT_NE(std::string{error.what()}.find("/nonexistent/layout.yaml: cannot open file"),
              std::string::npos);
  }
  const auto syntax = problems_of("regions: [\n");
  ASSERT_EQ(syntax.size(), 1u);
  EXPECT_GT(syntax[0].line, 0);
}

// yaml-cpp 0.7 never finishes reading a ',' outside a flow collection (jbeder/yaml-cpp#1040):
// LoadAll yields empty documents until memory runs out. Found by tests/fuzz/layout_yaml. In a
// child process with an alarm, so that a regression fails in seconds instead of filling memory.
TEST(layout_loader, a_stray_comma_is_a_syntax_error_not_a_hang) {
  EXPECT_EXIT(
      {
        alarm(20);
        const auto alone = problems_of(",");
        const auto after_a_list = problems_of("- [0, 0]\n,\n");
        const bool as_expected = alone.size() == 1 && alone[0].line == 1 && alone[0].column == 1 &&
                                 alone[0].message == "unexpected ','" && after_a_list.size() == 1 &&
                                 after_a_list[0].line == 2 && after_a_list[0].column == 1 &&
                                 after_a_list[0].message == "unexpected ','";
        std::exit(as_expected ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

// yaml-cpp reads a NUL as an escape even outside quotes ("a NUL _b" gives a lone 0xA0 byte,
// not UTF-8), as tests/fuzz/scenario_yaml found for scenarios: layouts refuse it alike.
TEST(layout_loader, a_nul_byte_is_refused_with_its_place) {
  const auto problems = problems_of(std::string(minimal) + std::string("name: a\0_b\n", 11));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].line, 5);
  EXPECT_EQ(problems[0].column, 8);
  EXPECT_EQ(problems[0].message, "unexpected NUL byte (YAML allows none in a file)");
}

}  // namespace
}  // namespace argus::world
