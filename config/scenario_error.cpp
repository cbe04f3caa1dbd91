#include "config/scenario_error.hpp"

#include <fmt/format.h>

namespace argus::config {

namespace {

std::string join_lines(const std::vector<problem>& problems) {
  std::string text;
  for (const auto& each : problems) {
    if (!text.empty()) text += '\n';
    text += to_string(each);
  }
  return text;
}

}  // namespace

std::string to_string(const problem& what) {
  std::string text = what.file;
  if (what.line > 0) {
    text += fmt::format(":{}", what.line);
    if (what.column > 0) text += fmt::format(":{}", what.column);
  }
  text += ": ";
  if (!what.field.empty()) text += what.field + ": ";
  text += what.message;
  return text;
}

scenario_error::scenario_error(std::vector<problem> problems)
    : std::runtime_error(join_lines(problems)), problems_(std::move(problems)) {
  // nop
}

}  // namespace argus::config
