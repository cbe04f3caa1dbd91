#include "python/set_texts.hpp"

#include <stdexcept>

#include "fmt/format.h"

namespace argus::pybridge {

std::vector<config::field_override> overrides_from(const std::vector<std::string>& texts) {
  std::vector<config::field_override> out;
  for (const auto& text : texts) {
    auto o = config::parse_field_override(text);
    if (!o)
      throw std::invalid_argument(
          fmt::format("set: expected KEY=VALUE with KEY a dotted scenario path, got '{}'", text));
    out.push_back(std::move(*o));
  }
  return out;
}

}  // namespace argus::pybridge
