#pragma once

// What a strategy plug-in exports: one entry point through which it registers its strategies.
// A plug-in is a shared library built against these headers (find_package(Argus)); `argus`
// loads it for `controller.strategy: plugin:PATH` or ARGUS_STRATEGY_PLUGINS, and resolves the
// symbols it uses from the `argus` executable itself. docs/strategies.md has a complete one.
//
//   ARGUS_STRATEGY_PLUGIN(registrar) {
//     registrar.add({"follow", [](const argus::controller::strategy_context& c) {
//       return std::make_unique<follow>(c.me);
//     }, false, "points at what it tracks, alone"});
//   }

#include "controller/strategy_registry.hpp"

namespace argus::controller {

/// Where a plug-in registers its strategies.
class strategy_registrar {
 public:
  virtual ~strategy_registrar() = default;
  virtual void add(strategy_entry entry) = 0;
};

}  // namespace argus::controller

/// The entry point's name carries the interface's version: a plug-in built against another
/// version lacks it, and is refused with that said.
#define ARGUS_STRATEGY_PLUGIN_ENTRY argus_strategy_plugin_v1
#define ARGUS_STRATEGY_PLUGIN_NAME "argus_strategy_plugin_v1"

/// Defines the entry point; its body registers strategies with `registrar`.
#define ARGUS_STRATEGY_PLUGIN(registrar)                                              \
  extern "C" __attribute__((visibility("default"))) void ARGUS_STRATEGY_PLUGIN_ENTRY( \
      ::argus::controller::strategy_registrar& registrar)
