#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "config/scenario_error.hpp"

namespace argus::config {

/// Where text first stops being UTF-8, 1-based like a compiler diagnostic (column in bytes).
struct utf8_break {
  int line = 1;
  int column = 1;
  unsigned char byte = 0;
};

/// The first byte of `text` that is not part of well-formed UTF-8 (overlong forms, surrogates
/// and code points past U+10FFFF included), or nothing when all of it is. YAML requires Unicode
/// text, and a name read from a file ends up in JSON outputs that cannot hold anything else.
std::optional<utf8_break> first_non_utf8(std::string_view text);

/// "expected UTF-8 text, got the byte 0xBB at byte N": for a one-line text (an option's value).
std::string expected_utf8(const utf8_break& where);

/// The problem to report for `file` whose text breaks off at `where`.
problem not_utf8(const std::string& file, const utf8_break& where);

}  // namespace argus::config
