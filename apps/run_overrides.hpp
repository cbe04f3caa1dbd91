#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "CLI/CLI.hpp"
#include "config/scenario.hpp"

namespace argus::apps {

/// The options `argus run` and `argus serve` share that override a scenario's `run` settings.
struct run_overrides {
  std::optional<std::uint64_t> seed;
  std::optional<unsigned> threads;
  std::optional<double> speed;
  std::optional<std::string> duration;
  std::optional<std::string> out;
};

/// Adds --seed, --threads, --speed, --duration and --out to `command`, read into `into`.
void add_run_override_options(CLI::App* command, run_overrides& into);

/// Applies `overrides` to `scenario`, validated like the file's own values; a bad value throws
/// CLI::ValidationError naming the option.
void apply_run_overrides(const run_overrides& overrides, config::scenario& scenario);

}  // namespace argus::apps
