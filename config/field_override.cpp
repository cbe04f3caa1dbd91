#include "config/field_override.hpp"

namespace argus::config {

std::optional<field_override> parse_field_override(std::string_view text) {
  const auto equals = text.find('=');
  if (equals == std::string_view::npos || equals == 0) return std::nullopt;
  const std::string_view path = text.substr(0, equals);
  if (path.front() == '.' || path.back() == '.' || path.find("..") != std::string_view::npos ||
      path.find_first_of(" \t") != std::string_view::npos)
    return std::nullopt;
  return field_override{std::string{path}, std::string{text.substr(equals + 1)}};
}

}  // namespace argus::config
