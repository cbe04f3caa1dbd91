#pragma once

#include "CLI/CLI.hpp"

namespace argus::apps {

/// Exit codes of the `argus` command line.
enum exit_code : int { ok = 0, run_failed = 1, bad_input = 2 };

/// Adds `argus run` to `app`; its callback sets `result` to the command's exit code.
void add_run_command(CLI::App& app, int& result);

/// Adds `argus validate` to `app`; its callback sets `result` to the command's exit code.
void add_validate_command(CLI::App& app, int& result);

}  // namespace argus::apps
