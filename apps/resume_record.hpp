#pragma once

// What made the runs in a sweep's or a chaos campaign's folder. Both commands resume: a run
// already done in the folder is not started again. That is only sound when the same argus ran
// the same scenario with the same settings; a rebuilt binary or an edited scenario would mix its
// runs with the older ones, and the tables would pair runs of two programs without a word.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "nlohmann/json.hpp"

namespace argus::apps {

/// A digest of `file`'s bytes (XXH3, 128 bits, in hex). Throws std::runtime_error, naming the
/// file, when it cannot be read.
std::string file_digest(const std::filesystem::path& file);

/// What makes a folder's runs: the argus executable the runs use (by its digest, so that a
/// rebuild to the same bytes is the same program), the scenario as loaded and written back
/// (`scenario_yaml`: its fields, not its comments; a file it names counts by its name), and the
/// command's `settings` that change a run or its verdict.
nlohmann::json made_with(const std::filesystem::path& program, std::string_view scenario_yaml,
                         nlohmann::json settings);

/// The file in a folder that records made_with().
inline constexpr std::string_view made_with_file = "made_with.json";

/// Checks `dir`'s record against `made`. A folder with no earlier runs (`has_runs` false) gets
/// `made` as its record and may be used. Otherwise nothing is returned when the record is the
/// same, and else the user's error: which of program, scenario and settings differ, then and
/// now (or that the runs were made by an argus that kept no record), and what to do. `command`
/// names the command ("argus sweep").
std::optional<std::string> check_resume(const std::filesystem::path& dir,
                                        const nlohmann::json& made, bool has_runs,
                                        std::string_view command);

}  // namespace argus::apps
