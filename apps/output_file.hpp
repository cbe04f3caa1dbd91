#pragma once

#include <filesystem>
#include <system_error>

namespace argus::apps {

/// Creates the folders an output file is to be written in, as users expect `--out a/b/c.png`
/// to work; a failure shows up when the file itself cannot be written.
inline void make_parent_folders(const std::filesystem::path& file) {
  std::error_code ignored;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ignored);
}

}  // namespace argus::apps
