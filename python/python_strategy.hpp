#pragma once

// A camera strategy written in Python (a subclass of argus.Strategy, python/argus/__init__.py):
// the C++ strategy that steps it, and the `python:MODULE:CLASS` source of the registry.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "controller/strategy_registry.hpp"
#include "pybind11/pybind11.h"

namespace argus::pybridge {

namespace py = pybind11;

/// A Python object shared by C++ owners that may outlive the interpreter (the registry is a
/// static): released under the GIL while the interpreter runs, left alone once it is gone.
std::shared_ptr<py::object> keep(py::object object);

/// What a Python strategy class is constructed with (argus.StrategyContext).
struct python_context {
  controller::node_identity me;
  double tick_s = 1.0 / 15.0;
  std::uint64_t seed = 0;
  std::string scenario;
  std::string strategy;
};

/// The registry entry of a Python strategy: `factory` (a class, or any callable taking an
/// argus.StrategyContext) makes one strategy object per camera. Called with the GIL held.
controller::strategy_entry python_entry(std::string name, py::object factory);

/// Serves `python:MODULE:CLASS` values of controller.strategy: imports MODULE (from PYTHONPATH
/// or the working directory) and takes its CLASS. `ready` is called
/// first, without the GIL: it starts the interpreter where none runs yet (the executable).
void serve_python_strategies(std::function<void()> ready);

}  // namespace argus::pybridge
