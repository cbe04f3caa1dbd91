#pragma once

#include <string>
#include <vector>

#include "pybind11/pybind11.h"

namespace argus::pybridge {

namespace py = pybind11;

/// argus.run's C++ half: loads `scenario_file` with the `KEY=VALUE` overrides `set`, names
/// `strategy` (a Python argus.Strategy subclass, or None for the scenario's) as its strategy,
/// runs it without the GIL and returns {"metrics", "summary", "output_dir", "paths",
/// "failure"} (failure: None, or why a strategy ended the run early). Called with the GIL.
py::dict run_from_python(const std::string& scenario_file, const std::vector<std::string>& set,
                         py::object strategy, bool progress);

}  // namespace argus::pybridge
