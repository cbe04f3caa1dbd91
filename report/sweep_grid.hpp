#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "report/sweep_results.hpp"

namespace argus::report {

/// `--set key=v1,v2,...` of `argus sweep`: the key and its values, split at the commas
/// outside brackets so a flow list (`[1, 2]`) stays one value. Nothing when the text is not
/// KEY=VALUES (see config::parse_field_override) or a value is empty.
std::optional<swept_parameter> parse_swept_parameter(std::string_view text);

/// One run to do: the grid point (a value per parameter) and a seed, named by `id`.
struct planned_run {
  std::string id;
  std::vector<std::string> values;
  std::uint64_t seed = 0;
};

/// Every combination of the parameters' values (the first parameter varying slowest) for each
/// seed 1..`seeds`. A run's id reads `key=value__key=value__seed=S` (last key segments;
/// characters a folder name should not hold become '_'), so a resumed sweep finds a run's folder
/// again as long as its values are the same, whatever else changed in the grid.
/// Seeds run from `first_seed` to `first_seed + seeds - 1`.
std::vector<planned_run> plan_runs(const std::vector<swept_parameter>& parameters,
                                   std::uint64_t seeds, std::uint64_t first_seed = 1);

}  // namespace argus::report
