#pragma once

#include <span>
#include <string>
#include <vector>

#include "config/field_override.hpp"
#include "config/scenario.hpp"

namespace argus::apps {

/// The scenario in `file` with the operator tasks of `--task` options appended, each written
/// `key=value,...` with the keys of a scenario's task (`at=10s,camera=7,pixel=160x120`; a
/// pixel as XxY). They are validated like the file's own tasks (config::scenario_error);
/// a malformed option throws CLI::ValidationError naming `--task`.
/// `overrides` (`--set`) apply first, as without --task.
config::scenario load_with_tasks(const std::string& file,
                                 std::span<const config::field_override> overrides,
                                 const std::vector<std::string>& tasks);

}  // namespace argus::apps
