#include "report/binary_file.hpp"

#include <fstream>
#include <iterator>

#include "config/whole_file.hpp"

namespace argus::report {

void write_file(const std::filesystem::path& file, std::span<const unsigned char> bytes) {
  config::write_whole_file(file, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
  });
}

void write_file(const std::filesystem::path& file, std::string_view text) {
  write_file(file, std::span{reinterpret_cast<const unsigned char*>(text.data()), text.size()});
}

std::optional<std::vector<unsigned char>> read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in),
                                    std::istreambuf_iterator<char>());
}

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return nullptr;
  auto parsed = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  return parsed.is_discarded() ? nlohmann::json(nullptr) : parsed;
}

}  // namespace argus::report
