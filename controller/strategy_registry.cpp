#include "controller/strategy_registry.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <map>
#include <mutex>
#include <stdexcept>

#include "config/scenario_error.hpp"
#include "controller/camera_controller.hpp"
#include "controller/oracle_strategy.hpp"
#include "controller/strategy_plugin.hpp"
#include "fmt/format.h"
#include "fmt/ranges.h"

namespace argus::controller {
namespace {

// The paper's controller, with collaboration or without.
strategy_factory camera_controller_with(bool collaborate) {
  return [collaborate](const strategy_context& c) -> std::unique_ptr<strategy> {
    return std::make_unique<camera_controller>(c.me, c.scenario, collaborate);
  };
}

struct registry {
  std::mutex mutex;
  std::map<std::string, strategy_entry, std::less<>> entries;
  // The plug-ins loaded, by path, with the names each registered (never unloaded: their
  // strategies' code stays in use until the process ends).
  std::map<std::string, std::vector<std::string>, std::less<>> plugins;
  // Sources of named strategies, by prefix (python:).
  std::map<std::string, strategy_source, std::less<>> sources;

  registry() {
    add({"paper", camera_controller_with(true), false,
         "the paper's Fig. 10 controller: ContractNet groups, hand-over, CSP (Section IV)"});
    add({"no_collaboration", camera_controller_with(false), false,
         "the same controller without groups: the tasked camera alone follows her"});
    add({"oracle",
         [](const strategy_context& c) -> std::unique_ptr<strategy> {
           return std::make_unique<oracle_strategy>(c.me, c.scenario, c.oracle());
         },
         true, "central assignment from ground truth, each camera tracking with its own sensor"});
  }
  void add(strategy_entry e) {
    auto name = e.name;
    entries.insert_or_assign(std::move(name), std::move(e));
  }
};

registry& the_registry() {
  static registry r;
  return r;
}

// Collects what a plug-in's entry point registers.
class collecting_registrar final : public strategy_registrar {
 public:
  void add(strategy_entry entry) override { entries.push_back(std::move(entry)); }
  std::vector<strategy_entry> entries;
};

[[noreturn]] void refuse(const config::scenario& scenario, std::string message) {
  config::problem p;
  p.file = scenario.source_path;
  p.field = "controller.strategy";
  p.message = std::move(message);
  throw config::scenario_error({std::move(p)});
}

[[noreturn]] void fail(std::string message) {
  throw std::runtime_error(std::move(message));
}

// `plugin:PATH` or `plugin:PATH#NAME`, split.
std::pair<std::string, std::string> plugin_path_and_name(std::string_view value) {
  auto rest = value.substr(std::string_view("plugin:").size());
  const auto hash = rest.rfind('#');
  if (hash == std::string_view::npos) return {std::string(rest), {}};
  return {std::string(rest.substr(0, hash)), std::string(rest.substr(hash + 1))};
}

std::string names_of(const std::vector<std::string>& names) {
  return fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace

std::vector<std::string> load_strategy_plugin(const std::string& path) {
  auto& r = the_registry();
  {
    std::lock_guard<std::mutex> guard(r.mutex);
    if (auto it = r.plugins.find(path); it != r.plugins.end()) return it->second;
  }
  void* library = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    const char* why = ::dlerror();
    fail(fmt::format("the strategy plug-in '{}' does not load: {}", path,
                     why != nullptr ? why : "unknown reason"));
  }
  using entry_point = void (*)(strategy_registrar&);
  auto* enter = reinterpret_cast<entry_point>(::dlsym(library, ARGUS_STRATEGY_PLUGIN_NAME));
  if (enter == nullptr) {
    ::dlclose(library);
    fail(
        fmt::format("the strategy plug-in '{}' lacks the entry point {} (define it with "
                    "ARGUS_STRATEGY_PLUGIN from controller/strategy_plugin.hpp; a plug-in built "
                    "for another version of Argus has another)",
                    path, ARGUS_STRATEGY_PLUGIN_NAME));
  }
  collecting_registrar registrar;
  enter(registrar);
  if (registrar.entries.empty())
    fail(fmt::format("the strategy plug-in '{}' registers no strategy", path));
  std::vector<std::string> names;
  std::lock_guard<std::mutex> guard(r.mutex);
  for (auto& e : registrar.entries) {
    names.push_back(e.name);
    e.source = path;
    r.add(std::move(e));
  }
  r.plugins.emplace(path, names);
  return names;
}

void load_listed_plugins() {
  const char* listed = std::getenv("ARGUS_STRATEGY_PLUGINS");
  if (listed == nullptr) return;
  std::string_view paths(listed);
  while (!paths.empty()) {
    const auto colon = paths.find(':');
    const auto path = paths.substr(0, colon);
    if (!path.empty()) load_strategy_plugin(std::string(path));
    if (colon == std::string_view::npos) break;
    paths.remove_prefix(colon + 1);
  }
}

void register_strategy_source(std::string prefix, strategy_source source) {
  auto& r = the_registry();
  std::lock_guard<std::mutex> guard(r.mutex);
  r.sources.insert_or_assign(std::move(prefix), std::move(source));
}

namespace {

// A value one of the sources serves: its entry, made once.
void resolve_from_source(const config::scenario& scenario) {
  const auto& value = scenario.controller.strategy;
  strategy_source source;
  {
    auto& r = the_registry();
    std::lock_guard<std::mutex> guard(r.mutex);
    if (r.entries.find(value) != r.entries.end()) return;
    for (const auto& [prefix, s] : r.sources)
      if (value.starts_with(prefix)) source = s;
  }
  if (!source) {
    if (value.starts_with("python:"))
      refuse(scenario, fmt::format("'{}': this argus was built without Python (ARGUS_PYTHON=OFF, "
                                   "as in sanitizer builds)",
                                   value));
    return;
  }
  strategy_entry entry;
  try {
    entry = source(value);
  } catch (const std::runtime_error& e) {
    refuse(scenario, e.what());
  }
  entry.name = value;
  register_strategy(std::move(entry));
}

}  // namespace

void register_strategy(strategy_entry entry) {
  auto& r = the_registry();
  std::lock_guard<std::mutex> guard(r.mutex);
  r.add(std::move(entry));
}

std::vector<strategy_entry> registered_strategies() {
  auto& r = the_registry();
  std::lock_guard<std::mutex> guard(r.mutex);
  std::vector<strategy_entry> out;
  for (const auto& [name, e] : r.entries) out.push_back(e);
  return out;
}

std::string strategy_name(const config::scenario& scenario) {
  const auto& value = scenario.controller.strategy;
  if (!value.starts_with("plugin:")) return value;
  auto [path, name] = plugin_path_and_name(value);
  if (!name.empty()) return name;
  auto& r = the_registry();
  std::lock_guard<std::mutex> guard(r.mutex);
  auto it = r.plugins.find(path);
  if (it == r.plugins.end() || it->second.size() != 1) return value;
  return it->second.front();
}

void resolve_strategy(const config::scenario& scenario) {
  try {
    load_listed_plugins();
  } catch (const std::runtime_error& e) {
    refuse(scenario, fmt::format("ARGUS_STRATEGY_PLUGINS: {}", e.what()));
  }
  const auto& value = scenario.controller.strategy;
  resolve_from_source(scenario);
  if (value.starts_with("plugin:")) {
    auto [path, name] = plugin_path_and_name(value);
    std::vector<std::string> names;
    try {
      names = load_strategy_plugin(path);
    } catch (const std::runtime_error& e) {
      refuse(scenario, e.what());
    }
    if (name.empty() && names.size() > 1)
      refuse(scenario, fmt::format("the strategy plug-in '{}' registers {} strategies ({}): name "
                                   "one as plugin:{}#NAME",
                                   path, names.size(), names_of(names), path));
  }
  const auto name = strategy_name(scenario);
  auto& r = the_registry();
  std::lock_guard<std::mutex> guard(r.mutex);
  if (r.entries.find(name) != r.entries.end()) return;
  std::vector<std::string> known;
  for (const auto& [n, e] : r.entries) known.push_back(n);
  refuse(scenario, fmt::format("no strategy is named '{}' (registered: {}; a plug-in's are "
                               "loaded with plugin:PATH or ARGUS_STRATEGY_PLUGINS)",
                               name, names_of(known)));
}

bool is_oracle(const config::scenario& scenario) {
  const auto name = strategy_name(scenario);
  auto& r = the_registry();
  std::lock_guard<std::mutex> guard(r.mutex);
  auto it = r.entries.find(name);
  return it != r.entries.end() && it->second.oracle;
}

std::unique_ptr<strategy> make_strategy(const node_identity& me, const config::scenario& scenario,
                                        const oracle_source& oracle) {
  const auto name = strategy_name(scenario);
  strategy_entry entry;
  {
    auto& r = the_registry();
    std::lock_guard<std::mutex> guard(r.mutex);
    auto it = r.entries.find(name);
    if (it == r.entries.end()) refuse(scenario, fmt::format("no strategy is named '{}'", name));
    entry = it->second;
  }
  strategy_context context{me, scenario, {}};
  if (entry.oracle) {
    if (!oracle)
      refuse(scenario, fmt::format("'{}' is an oracle and needs ground truth, which this run "
                                   "does not lend camera {}",
                                   name, me.id));
    context.oracle = oracle;
  }
  return entry.make(context);
}

}  // namespace argus::controller
