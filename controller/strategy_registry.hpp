#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "config/scenario.hpp"
#include "controller/oracle_view.hpp"
#include "controller/strategy.hpp"

namespace argus::controller {

/// Makes the ground-truth view of one camera; null where the host has none (a node without a
/// world, in network tests).
using oracle_source = std::function<std::unique_ptr<oracle_view>()>;

/// What a strategy is made from, per camera node.
struct strategy_context {
  node_identity me;
  const config::scenario& scenario;
  /// Ground truth: set only for a strategy registered as an oracle.
  oracle_source oracle;
};

using strategy_factory = std::function<std::unique_ptr<strategy>(const strategy_context&)>;

/// A strategy by name, as `controller.strategy` names it.
struct strategy_entry {
  std::string name;
  strategy_factory make;
  /// Whether it may see ground truth (controller/oracle_view.hpp): its figures are then an upper
  /// bound, not a camera network's.
  bool oracle = false;
  /// One line for `argus strategies` and error messages.
  std::string summary;
  /// Where it comes from: "built-in", or the plug-in's path (set by the registry).
  std::string source = "built-in";
};

/// Adds (or replaces) a strategy under its name. Built-ins are registered at start-up.
void register_strategy(strategy_entry entry);

/// Makes the entry of a strategy named by a `controller.strategy` value with a source's prefix
/// (`python:MODULE:CLASS`); throws std::runtime_error saying what is wrong.
using strategy_source = std::function<strategy_entry(const std::string& value)>;

/// Serves `controller.strategy` values starting with `prefix` ("python:"): resolve_strategy
/// asks `source` once per value not registered yet and registers what it returns under it.
void register_strategy_source(std::string prefix, strategy_source source);

/// The registered strategies, by name.
std::vector<strategy_entry> registered_strategies();

/// Loads the strategy plug-in at `path` (once; again returns the same), registering what it
/// registers; returns those names. Throws std::runtime_error naming the library when it does not
/// load, lacks the entry point or registers nothing.
std::vector<std::string> load_strategy_plugin(const std::string& path);

/// Loads the plug-ins the environment variable ARGUS_STRATEGY_PLUGINS lists (paths separated
/// by ':'); throws as load_strategy_plugin does.
void load_listed_plugins();

/// The registered name `controller.strategy` stands for: the name itself, or the strategy a
/// plug-in loaded for `plugin:PATH` registered (`plugin:PATH#NAME` for one of several).
std::string strategy_name(const config::scenario& scenario);

/// Makes `controller.strategy` usable: loads its plug-in if it names one (and those listed in
/// the environment variable ARGUS_STRATEGY_PLUGINS, separated by ':'), and checks that the
/// strategy is registered. Throws config::scenario_error naming the scenario file, the field
/// and what is wrong: a library that does not load, lacks the entry point, or registers no such
/// strategy.
void resolve_strategy(const config::scenario& scenario);

/// Whether the strategy `controller.strategy` names is registered as an oracle.
bool is_oracle(const config::scenario& scenario);

/// The strategy of camera `me` in `scenario`. Throws std::runtime_error naming the strategy when
/// none is registered under that name, or when an oracle is asked for and `oracle` is empty.
std::unique_ptr<strategy> make_strategy(const node_identity& me, const config::scenario& scenario,
                                        const oracle_source& oracle = {});

}  // namespace argus::controller
