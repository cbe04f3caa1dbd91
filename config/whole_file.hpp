#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>

namespace argus::config {

/// Writes `path` through `write` under a temporary name beside it and renames it when
/// complete, so that a reader (a browser, a resumed sweep, the next run) never sees half a
/// file and a failed run leaves none; throws std::runtime_error naming the file.
void write_whole_file(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write);

/// The bytes of `path`; throws std::runtime_error naming the file when it cannot be read.
std::string read_whole_file(const std::filesystem::path& path);

}  // namespace argus::config
