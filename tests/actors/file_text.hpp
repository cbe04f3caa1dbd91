#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace argus::actors::testing {

/// The whole of a file, byte for byte (empty when it cannot be read): for comparing runs' logs.
inline std::string file_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace argus::actors::testing
