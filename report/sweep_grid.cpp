#include "report/sweep_grid.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cstdint>
#include <set>

#include "config/field_override.hpp"

namespace argus::report {

namespace {

std::vector<std::string> split_outside_brackets(const std::string& text) {
  std::vector<std::string> out(1);
  int depth = 0;
  for (char c : text) {
    if (c == '[' || c == '{') ++depth;
    if (c == ']' || c == '}') --depth;
    if (c == ',' && depth == 0)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

std::string folder_safe(const std::string& text) {
  std::string out;
  for (char c : text)
    out +=
        std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_' ? c : '_';
  return out;
}

// The last segment of each key, unless two keys share it: then the whole key.
std::vector<std::string> short_names(const std::vector<swept_parameter>& parameters) {
  std::vector<std::string> out;
  std::multiset<std::string> lasts;
  for (const auto& p : parameters) {
    const auto dot = p.key.rfind('.');
    out.push_back(dot == std::string::npos ? p.key : p.key.substr(dot + 1));
    lasts.insert(out.back());
  }
  for (std::size_t k = 0; k < out.size(); ++k)
    if (lasts.count(out[k]) > 1) out[k] = parameters[k].key;
  return out;
}

}  // namespace

std::optional<swept_parameter> parse_swept_parameter(std::string_view text) {
  const auto field = config::parse_field_override(text);
  if (!field) return std::nullopt;
  swept_parameter out{field->path, split_outside_brackets(field->value)};
  for (const auto& value : out.values)
    if (value.empty()) return std::nullopt;
  return out;
}

// A folder name holds at most 255 bytes; the seed and a "v2" suffix must still fit.
constexpr std::size_t max_prefix_bytes = 200;

// Many swept keys (16 cameras' fields) would overflow a folder name: the start is kept for a
// reader and a hash of the whole (FNV-1a, the same in every process, so a resumed sweep finds
// its runs) keeps points apart.
std::string shortened(const std::string& prefix) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : prefix) hash = (hash ^ c) * 1099511628211ull;
  return fmt::format("{}h{:016x}__", prefix.substr(0, max_prefix_bytes - 20), hash);
}

std::vector<planned_run> plan_runs(const std::vector<swept_parameter>& parameters,
                                   std::uint64_t seeds, std::uint64_t first_seed) {
  std::vector<std::vector<std::string>> points{{}};
  for (const auto& p : parameters) {
    std::vector<std::vector<std::string>> longer;
    for (const auto& point : points)
      for (const auto& value : p.values) {
        longer.push_back(point);
        longer.back().push_back(value);
      }
    points = std::move(longer);
  }
  const auto names = short_names(parameters);
  std::vector<planned_run> out;
  std::set<std::string> prefixes;
  for (const auto& point : points) {
    std::string prefix;
    for (std::size_t k = 0; k < point.size(); ++k)
      prefix += folder_safe(names[k]) + "=" + folder_safe(point[k]) + "__";
    if (prefix.size() > max_prefix_bytes) prefix = shortened(prefix);
    // Values that differ only in characters a folder name cannot hold ("[1, 2]", "[1,2]")
    // would share a folder: the later point is numbered.
    const std::string base = prefix;
    for (int n = 2; !prefixes.insert(prefix).second; ++n)
      prefix = base + "v" + std::to_string(n) + "__";
    for (std::uint64_t seed = first_seed; seed < first_seed + seeds; ++seed)
      out.push_back({prefix + "seed=" + std::to_string(seed), point, seed});
  }
  return out;
}

}  // namespace argus::report
