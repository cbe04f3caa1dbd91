#include "config/utf8_text.hpp"

#include <fmt/format.h>

#include <cstddef>

namespace argus::config {

namespace {

/// The length of the well-formed sequence starting at `at`, or 0 if there is none.
std::size_t sequence_length(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
  const auto continuation = [&](std::size_t k, unsigned char low = 0x80,
                                unsigned char high = 0xBF) {
    return at + k < text.size() && byte(k) >= low && byte(k) <= high;
  };
  const unsigned char lead = byte(0);
  if (lead < 0x80) return 1;
  // Unicode 15, table 3-7: the second byte's range depends on the lead, which rules out
  // overlong forms, surrogates and code points past U+10FFFF.
  if (lead >= 0xC2 && lead <= 0xDF) return continuation(1) ? 2 : 0;
  if (lead == 0xE0) return continuation(1, 0xA0) && continuation(2) ? 3 : 0;
  if (lead == 0xED) return continuation(1, 0x80, 0x9F) && continuation(2) ? 3 : 0;
  if (lead >= 0xE1 && lead <= 0xEF) return continuation(1) && continuation(2) ? 3 : 0;
  if (lead == 0xF0) return continuation(1, 0x90) && continuation(2) && continuation(3) ? 4 : 0;
  if (lead >= 0xF1 && lead <= 0xF3)
    return continuation(1) && continuation(2) && continuation(3) ? 4 : 0;
  if (lead == 0xF4)
    return continuation(1, 0x80, 0x8F) && continuation(2) && continuation(3) ? 4 : 0;
  return 0;
}

}  // namespace

std::optional<utf8_break> first_non_utf8(std::string_view text) {
  utf8_break at;
  std::size_t line_start = 0;
  for (std::size_t k = 0; k < text.size();) {
    const auto length = sequence_length(text, k);
    if (length == 0) {
      at.column = static_cast<int>(k - line_start) + 1;
      at.byte = static_cast<unsigned char>(text[k]);
      return at;
    }
    if (text[k] == '\n') {
      ++at.line;
      line_start = k + 1;
    }
    k += length;
  }
  return std::nullopt;
}

std::string expected_utf8(const utf8_break& where) {
  return fmt::format("expected UTF-8 text, got the byte 0x{:02X} at byte {}", where.byte,
                     where.column);
}

problem not_utf8(const std::string& file, const utf8_break& where) {
  return problem{file,
                 where.line,
                 where.column,
                 {},
                 fmt::format("expected UTF-8 text (YAML is Unicode), got the byte 0x{:02X}; "
                             "save the file as UTF-8",
                             where.byte)};
}

}  // namespace argus::config
