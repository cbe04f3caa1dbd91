#pragma once

#include <string>
#include <vector>

#include "config/scenario.hpp"

namespace argus::apps {

/// The scenario in `file` with the operator tasks of `--task` options appended, each written
/// `key=value,...` with the keys of a scenario's task (`at=10s,camera=7,pixel=160x120`; a
/// pixel as XxY). They are validated like the file's own tasks (config::scenario_error);
/// a malformed option throws CLI::ValidationError naming `--task`.
config::scenario load_with_tasks(const std::string& file, const std::vector<std::string>& tasks);

}  // namespace argus::apps
