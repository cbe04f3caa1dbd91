#pragma once

// Guards against inputs that Debian 12's yaml-cpp (0.7) mishandles, run before it reads a
// file: the scenario and layout loaders share them.

#include <optional>
#include <string>
#include <string_view>

#include "config/scenario_error.hpp"

namespace argus::config {

/// yaml-cpp 0.7 reads a NUL byte as the start of an escape sequence, even in a plain scalar,
/// and writes some escapes as bytes that are not UTF-8 (`NUL _` becomes a lone 0xA0): a value
/// of valid UTF-8 text would come out as invalid text. YAML allows no NUL in a file, so the
/// first one is a problem of `source`, at its line and column (counted in bytes).
std::optional<problem> nul_byte(const std::string& source, std::string_view text);

/// Refuses the YAML that yaml-cpp 0.7 never finishes reading: a ',' outside a flow collection
/// (`,` or `- 1\n,`) makes its parser yield empty documents forever without moving on, so
/// LoadAll fills memory until the process dies (jbeder/yaml-cpp#1040, fixed in 0.8.0). The
/// documents are walked first; one that starts where the previous one did is reported as a
/// syntax error at that place. Throws YAML::ParserException, as LoadAll does for bad syntax.
void refuse_stuck_documents(const std::string& text);

}  // namespace argus::config
