// Strategies by name: the built-ins, one registered as a plug-in would, and the errors a user
// sees for a name nobody registered or an oracle without ground truth, naming the field.

#include "controller/strategy_registry.hpp"

#include <gtest/gtest.h>

#include "config/scenario_error.hpp"
#include "controller/camera_controller.hpp"
#include "controller/oracle_strategy.hpp"

namespace argus::controller {
namespace {

class idle_strategy final : public strategy {
 public:
  controller_output step(const controller_input&) override { return {}; }
  strategy_status status() const override { return {}; }
};

config::scenario named(std::string strategy) {
  config::scenario s;
  s.source_path = "test.yaml";
  s.controller.strategy = std::move(strategy);
  return s;
}

TEST(strategy_registry, makes_the_built_ins_by_name) {
  node_identity me;
  me.id = 4;
  EXPECT_NE(dynamic_cast<camera_controller*>(make_strategy(me, named("paper")).get()), nullptr);
  EXPECT_NE(dynamic_cast<camera_controller*>(make_strategy(me, named("no_collaboration")).get()),
            nullptr);
  EXPECT_FALSE(is_oracle(named("paper")));
  EXPECT_TRUE(is_oracle(named("oracle")));
}

TEST(strategy_registry, makes_a_registered_strategy_and_lists_it) {
  register_strategy({"registry_test_idle",
                     [](const strategy_context&) { return std::make_unique<idle_strategy>(); },
                     false, "does nothing"});
  const auto s = named("registry_test_idle");
  EXPECT_NO_THROW(resolve_strategy(s));
  EXPECT_NE(dynamic_cast<idle_strategy*>(make_strategy({}, s).get()), nullptr);
  bool listed = false;
  for (const auto& e : registered_strategies()) listed |= e.name == "registry_test_idle";
  EXPECT_TRUE(listed);
}

TEST(strategy_registry, an_unknown_name_is_refused_naming_the_file_the_field_and_the_known) {
  try {
    resolve_strategy(named("no_such_strategy"));
    FAIL() << "resolved";
  } catch (const config::scenario_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("test.yaml"), std::string::npos) << what;
    EXPECT_NE(what.find("controller.strategy"), std::string::npos) << what;
    EXPECT_NE(what.find("no strategy is named 'no_such_strategy'"), std::string::npos) << what;
    EXPECT_NE(what.find("paper"), std::string::npos) << what;
  }
}

TEST(strategy_registry, an_oracle_is_made_only_with_ground_truth_to_lend) {
  EXPECT_THROW(make_strategy({}, named("oracle")), config::scenario_error);
}

TEST(strategy_registry, a_plugin_that_does_not_load_is_refused_naming_the_library) {
  try {
    resolve_strategy(named("plugin:/nonexistent/strategy.so"));
    FAIL() << "resolved";
  } catch (const config::scenario_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'/nonexistent/strategy.so' does not load"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace argus::controller
