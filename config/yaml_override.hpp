#pragma once

#include <yaml-cpp/yaml.h>

#include <span>
#include <string>

#include "config/field_override.hpp"

namespace argus::config {

/// Puts each override's value into `document` at its path, creating the mappings on the way,
/// so the scenario parser then validates it like a value of the file. The values carry no
/// position, so a problem with one names its field but no line of the file it never was in.
/// Throws scenario_error (naming `source_name` and the path) for a value that is not YAML, an
/// index past a list's end, or a path that goes through a plain value. Internal to
/// argus_config: its header needs yaml-cpp.
void apply_overrides(YAML::Node& document, std::span<const field_override> overrides,
                     const std::string& source_name);

}  // namespace argus::config
