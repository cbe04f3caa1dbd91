#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace argus::config {

/// One `--set KEY=VALUE` from the command line: a scenario field named by its YAML path
/// (`network.loss_probability`, `tasks.0.cameras_wanted`) and the YAML text to put there.
/// Overrides edit the YAML tree before validation, so a bad key or value gets the loader's
/// own message naming the field, exactly as if the file had said it.
struct field_override {
  /// Dot-separated path; a number selects a list entry (0-based), `*` every entry
  /// (`cameras.*.imaging.noise_sigma`).
  std::string path;
  /// YAML text: a scalar (`0.2`, `all_solv`, `2 min`) or a flow collection (`[1, 2]`).
  std::string value;

  friend bool operator==(const field_override&, const field_override&) = default;
};

/// Splits `KEY=VALUE` at its first '='; nothing when the key is empty, has an empty
/// segment (`a..b`) or there is no '='.
std::optional<field_override> parse_field_override(std::string_view text);

}  // namespace argus::config
