#include "report/binary_file.hpp"

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <system_error>

namespace argus::report {

void write_file(const std::filesystem::path& file, std::span<const unsigned char> bytes) {
  auto partial = file;
  partial += ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + file.string());
  }
  std::error_code error;
  std::filesystem::rename(partial, file, error);
  if (error) throw std::runtime_error("cannot write " + file.string() + ": " + error.message());
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
