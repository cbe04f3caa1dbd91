#pragma once

#include <string>
#include <vector>

#include "config/field_override.hpp"

namespace argus::pybridge {

/// The overrides `KEY=VALUE` texts name (argus.run's and parallel_env's `set`); throws
/// std::invalid_argument (a Python ValueError) naming a text that is not KEY=VALUE.
std::vector<config::field_override> overrides_from(const std::vector<std::string>& texts);

}  // namespace argus::pybridge
