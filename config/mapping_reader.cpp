#include "config/mapping_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "config/duration.hpp"
#include "config/edit_distance.hpp"

namespace argus::config {

mapping_reader::mapping_reader(yaml_reader& reader, const YAML::Node& node, std::string path,
                               std::span<const std::string_view> keys)
    : reader_(reader), path_(std::move(path)), mark_(node.Mark()) {
  if (node.IsNull()) {
    is_mapping_ = true;
    return;
  }
  if (!node.IsMap()) {
    reader_.report(node, path_, "expected a mapping, got " + yaml_reader::describe(node));
    return;
  }
  is_mapping_ = true;
  for (const auto& pair : node) {
    const YAML::Node& key = pair.first;
    if (!key.IsScalar()) {
      reader_.report(key, path_, "expected a key name, got " + yaml_reader::describe(key));
      continue;
    }
    const std::string& name = key.Scalar();
    if (std::find(keys.begin(), keys.end(), name) == keys.end()) {
      auto message =
          fmt::format("unknown key '{}' (expected one of: {})", name, fmt::join(keys, ", "));
      if (const auto hint = closest_match(name, keys)) {
        message += fmt::format("; did you mean '{}'?", *hint);
      }
      reader_.report(key, field(name), std::move(message));
      continue;
    }
    const auto earlier = std::find_if(entries_.begin(), entries_.end(),
                                      [&](const entry& seen) { return seen.key == name; });
    if (earlier != entries_.end()) {
      reader_.report(key, field(name),
                     fmt::format("duplicate key '{}' (first given at line {})", name,
                                 earlier->key_mark.line + 1));
      continue;
    }
    entries_.push_back({name, key.Mark(), pair.second});
  }
}

std::optional<YAML::Node> mapping_reader::find(std::string_view key) const {
  for (const auto& each : entries_) {
    if (each.key == key) return each.value;
  }
  return std::nullopt;
}

std::string mapping_reader::field(std::string_view key) const {
  return path_.empty() ? std::string{key} : fmt::format("{}.{}", path_, key);
}

bool mapping_reader::require(std::string_view key, std::string_view why) {
  if (find(key)) return true;
  if (is_mapping_) {
    auto message = fmt::format("missing required key '{}'", key);
    if (!why.empty()) message += fmt::format(" ({})", why);
    reader_.report(mark_, field(key), std::move(message));
  }
  return false;
}

void mapping_reader::check_default(std::string_view key, double value, const value_bounds& bounds,
                                   std::string_view note) {
  if (find(key) || bounds.contains(value)) return;
  reader_.report(mark_, field(key),
                 yaml_reader::out_of_range("a number", bounds.describe(), note,
                                           fmt::format("{} (the default)", value)));
}

void mapping_reader::check_default(std::string_view key, seconds value, const value_bounds& bounds,
                                   std::string_view note) {
  if (find(key) || bounds.contains(value.count())) return;
  const auto bounds_text =
      bounds.describe([](double limit) { return format_duration(seconds{limit}); });
  reader_.report(mark_, field(key),
                 yaml_reader::out_of_range("a duration", bounds_text, note,
                                           format_duration(value) + " (the default)"));
}

}  // namespace argus::config
