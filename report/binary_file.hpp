#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "nlohmann/json.hpp"

namespace argus::report {

/// Writes `bytes` to `file` whole (config::write_whole_file).
void write_file(const std::filesystem::path& file, std::span<const unsigned char> bytes);

/// write_file for text.
void write_file(const std::filesystem::path& file, std::string_view text);

/// The bytes of `file`; nothing when it cannot be read.
std::optional<std::vector<unsigned char>> read_file(const std::filesystem::path& file);

/// The JSON document in `file`; null when it is absent or does not parse (a run killed while
/// writing it).
nlohmann::json read_json(const std::filesystem::path& file);

}  // namespace argus::report
