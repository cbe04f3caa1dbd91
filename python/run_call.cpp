#include "python/run_call.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "actors/run_scenario.hpp"
#include "config/field_override.hpp"
#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "fmt/format.h"
#include "python/python_strategy.hpp"
#include "python/set_texts.hpp"

namespace argus::pybridge {
namespace {

py::object read_json(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return py::none();
  std::stringstream text;
  text << in.rdbuf();
  return py::module_::import("json").attr("loads")(text.str());
}

// python:MODULE:QUALNAME of a class passed to argus.run.
std::string name_of(const py::object& strategy) {
  const auto module = py::str(py::getattr(strategy, "__module__", py::str("__main__")));
  const auto qualname = py::str(
      py::getattr(strategy, "__qualname__", py::getattr(strategy, "__name__", py::str("?"))));
  return fmt::format("python:{}:{}", module.cast<std::string>(), qualname.cast<std::string>());
}

}  // namespace

py::dict run_from_python(const std::string& scenario_file, const std::vector<std::string>& set,
                         py::object strategy, bool progress) {
  auto scenario = config::load_scenario(scenario_file, overrides_from(set));
  if (!strategy.is_none()) {
    const auto name = name_of(strategy);
    controller::register_strategy(python_entry(name, strategy));
    scenario.controller.strategy = name;
  }
  actors::run_options options;
  options.show_progress = progress;
  actors::run_outcome outcome;
  {
    py::gil_scoped_release free;
    outcome = actors::run_scenario(scenario, options);
  }
  const auto& dir = outcome.output_dir;
  py::dict paths;
  for (const char* file : {"events.jsonl", "summary.json", "metrics.json", "trajectories.csv",
                           "tracks.csv", "targets.csv", "poses.csv"})
    paths[py::str(std::filesystem::path(file).stem().string())] = (dir / file).string();
  py::dict result;
  result["metrics"] = read_json(dir / "metrics.json");
  result["summary"] = read_json(dir / "summary.json");
  result["output_dir"] = dir.string();
  result["paths"] = paths;
  result["failure"] = outcome.result.failure.empty() ? py::object(py::none())
                                                     : py::object(py::str(outcome.result.failure));
  return result;
}

}  // namespace argus::pybridge
