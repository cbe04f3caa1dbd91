#include "config/field_override.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "config/scenario_loader.hpp"

namespace argus::config {
namespace {

// A scenario with a list to index into; `--set` edits it before validation.
constexpr std::string_view base = R"(name: base
world: {population: 20}
cameras:
  - {id: 1, position: [1, 1]}
  - {id: 2, position: [9, 1]}
tasks:
  - {at: 2 s, pedestrian: 1, camera: 1, cameras_wanted: 2}
)";

scenario with(std::vector<field_override> overrides) {
  return parse_scenario(base, "base.yaml", overrides);
}

std::string error_of(std::vector<field_override> overrides) {
  try {
    with(std::move(overrides));
  } catch (const scenario_error& e) {
    return e.what();
  }
  return "";
}

TEST(field_override, splits_at_the_first_equals_sign) {
  EXPECT_EQ(parse_field_override("run.duration=2 min"), (field_override{"run.duration", "2 min"}));
  EXPECT_EQ(parse_field_override("a.b=x=y"), (field_override{"a.b", "x=y"}));
  EXPECT_EQ(parse_field_override("a="), (field_override{"a", ""}));
  EXPECT_FALSE(parse_field_override("no_equals"));
  EXPECT_FALSE(parse_field_override("=3"));
  EXPECT_FALSE(parse_field_override("a..b=3"));
  EXPECT_FALSE(parse_field_override(".a=3"));
}

TEST(field_override, sets_existing_and_new_fields) {
  const auto s = with({{"world.population", "50"},
                       {"network.loss_probability", "0.2"},
                       {"controller.solver", "all_solv"},
                       {"run.duration", "3 s"}});
  EXPECT_EQ(s.world.population, 50u);
  EXPECT_DOUBLE_EQ(s.network.loss_probability, 0.2);
  EXPECT_EQ(s.controller.solver, conflict_solver::all_solv);
  EXPECT_DOUBLE_EQ(s.run.duration.count(), 3.0);
}

TEST(field_override, indexes_lists_and_takes_flow_values) {
  const auto s = with({{"tasks.0.cameras_wanted", "1"}, {"cameras.1.position", "[5, 6]"}});
  EXPECT_EQ(s.tasks.at(0).cameras_wanted, 1u);
  EXPECT_DOUBLE_EQ(s.cameras.at(1).position.x_m, 5.0);
  EXPECT_DOUBLE_EQ(s.cameras.at(1).position.y_m, 6.0);
}

TEST(field_override, a_star_sets_the_field_in_every_entry_of_a_list) {
  const auto s = with({{"cameras.*.imaging", "{resolution: [64, 48], noise_sigma: 2}"},
                       {"cameras.0.imaging.resolution", "[32, 24]"},
                       {"cameras.*.height_m", "7"}});
  ASSERT_EQ(s.cameras.size(), 2u);
  // The later override inside one entry reaches that entry alone: each got its own copy.
  EXPECT_EQ(s.cameras[0].imaging.width_px, 32u);
  EXPECT_EQ(s.cameras[0].imaging.height_px, 24u);
  EXPECT_EQ(s.cameras[1].imaging.width_px, 64u);
  EXPECT_EQ(s.cameras[1].imaging.height_px, 48u);
  for (const auto& camera : s.cameras) EXPECT_DOUBLE_EQ(camera.imaging.noise_sigma, 2.0);
  for (const auto& camera : s.cameras) EXPECT_DOUBLE_EQ(camera.height_m, 7.0);
  // Fields the star does not name stay as the file says.
  EXPECT_DOUBLE_EQ(s.cameras[1].position.x_m, 9.0);
}

TEST(field_override, a_star_needs_a_list_with_entries) {
  const auto on_map = error_of({{"world.*", "1"}});
  EXPECT_NE(on_map.find("'*' stands for every entry of a list; world is not a list"),
            std::string::npos)
      << on_map;
  const auto deeper = error_of({{"cameras.*.position.x", "1"}});
  EXPECT_NE(deeper.find("cameras.0.position is a list of 2"), std::string::npos) << deeper;
}

TEST(field_override, later_overrides_win) {
  EXPECT_EQ(with({{"world.population", "5"}, {"world.population", "7"}}).world.population, 7u);
}

TEST(field_override, bad_keys_and_values_get_the_loaders_messages) {
  const auto typo = error_of({{"network.loss_probabilty", "0.2"}});
  EXPECT_NE(typo.find("unknown key 'loss_probabilty'"), std::string::npos) << typo;
  EXPECT_NE(typo.find("did you mean 'loss_probability'"), std::string::npos) << typo;
  const auto range = error_of({{"network.loss_probability", "2"}});
  EXPECT_NE(range.find("network.loss_probability: expected"), std::string::npos) << range;
  // The value was never in the file, so no line of it is named.
  EXPECT_EQ(range.rfind("base.yaml: ", 0), 0u) << range;
}

TEST(field_override, paths_that_do_not_fit_the_tree_are_named) {
  const auto past_end = error_of({{"tasks.3.camera", "1"}});
  EXPECT_NE(past_end.find("tasks.3.camera: --set: tasks is a list of 1"), std::string::npos)
      << past_end;
  const auto through_value = error_of({{"world.population.x", "1"}});
  EXPECT_NE(through_value.find("world.population is a value ('20')"), std::string::npos)
      << through_value;
  const auto not_yaml = error_of({{"world.population", "[1, 2"}});
  EXPECT_NE(not_yaml.find("is not a YAML value"), std::string::npos) << not_yaml;
}

}  // namespace
}  // namespace argus::config
