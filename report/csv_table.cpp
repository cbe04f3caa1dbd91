#include "report/csv_table.hpp"

#include <charconv>
#include <fstream>
#include <sstream>

namespace argus::report {

namespace {

std::vector<std::string> csv_fields_of(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::vector<std::string> out;
  std::size_t from = 0;
  while (true) {
    const auto comma = line.find(',', from);
    out.emplace_back(line.substr(from, comma - from));
    if (comma == std::string_view::npos) return out;
    from = comma + 1;
  }
}

}  // namespace

std::optional<csv_table> csv_table::read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  auto table = parse(text.str());
  if (table.header_.empty()) return std::nullopt;
  return table;
}

csv_table csv_table::parse(std::string_view text) {
  csv_table out;
  std::size_t from = 0;
  while (from < text.size()) {
    auto end = text.find('\n', from);
    if (end == std::string_view::npos) end = text.size();
    const auto line = text.substr(from, end - from);
    from = end + 1;
    if (line.empty() || line == "\r") continue;
    auto fields = csv_fields_of(line);
    if (out.header_.empty())
      out.header_ = std::move(fields);
    else if (fields.size() >= out.header_.size())
      out.rows_.push_back(std::move(fields));
  }
  return out;
}

std::optional<std::size_t> csv_table::column(std::string_view name) const {
  for (std::size_t k = 0; k < header_.size(); ++k)
    if (header_[k] == name) return k;
  return std::nullopt;
}

double csv_table::number(const std::vector<std::string>& row, std::size_t column, double fallback) {
  if (column >= row.size()) return fallback;
  const auto& text = row[column];
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc{} && end == text.data() + text.size() ? value : fallback;
}

}  // namespace argus::report
