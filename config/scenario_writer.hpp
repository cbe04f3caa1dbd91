#pragma once

#include <string>

#include "config/scenario.hpp"

namespace argus::config {

/// The effective configuration of `s` as a scenario file: every field written, defaults
/// included, durations via format_duration and enums by their YAML names, so a run's output
/// records exactly what it ran. `parse_scenario(to_yaml(s), ...)` gives back `s` (apart
/// from `source_path`, which names the file rather than being part of it).
std::string to_yaml(const scenario& s);

}  // namespace argus::config
