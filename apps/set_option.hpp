#pragma once

// `--set KEY=VALUE`, shared by the commands that load a scenario (run, validate): a scenario
// field overridden by its YAML path before validation (config/field_override.hpp).

#include <string>
#include <vector>

#include "CLI/CLI.hpp"
#include "config/field_override.hpp"
#include "fmt/format.h"

namespace argus::apps {

/// Adds the repeatable `--set` to `command`, collecting the texts into `texts`; a text that is
/// not KEY=VALUE is a command-line error naming the option.
inline CLI::Option* add_set_option(CLI::App* command, std::vector<std::string>& texts) {
  return command
      ->add_option("--set", texts,
                   "Override a scenario field by its YAML path, e.g. "
                   "network.loss_probability=0.2 or tasks.0.cameras_wanted=3 (repeatable)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            if (config::parse_field_override(text)) return {};
            return fmt::format(
                "expected KEY=VALUE with KEY a dotted scenario path, e.g. "
                "network.loss_probability=0.2, got '{}'",
                text);
          },
          "KEY=VALUE"))
      ->allow_extra_args(false);
}

/// The overrides the `--set` texts name, in order (add_set_option checked them).
inline std::vector<config::field_override> overrides_from(const std::vector<std::string>& texts) {
  std::vector<config::field_override> out;
  for (const auto& text : texts) out.push_back(*config::parse_field_override(text));
  return out;
}

}  // namespace argus::apps
