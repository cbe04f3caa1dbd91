#pragma once

#include "pybind11/pybind11.h"

namespace argus::pybridge {

/// Defines the module `_argus` (what python/argus/__init__.py re-exports): the strategy
/// interface's types, argus.run's and argus.parallel_env's C++ halves. The extension and the
/// executable's embedded interpreter define the same module with it.
void bind_all(pybind11::module_& m);

}  // namespace argus::pybridge
