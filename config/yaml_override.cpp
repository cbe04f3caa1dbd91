#include "config/yaml_override.hpp"

#include <fmt/format.h>

#include <charconv>
#include <optional>
#include <vector>

#include "config/scenario_error.hpp"
#include "config/utf8_text.hpp"

namespace argus::config {

namespace {

std::vector<std::string> segments_of(const std::string& path) {
  std::vector<std::string> out;
  std::size_t from = 0;
  while (true) {
    const auto dot = path.find('.', from);
    out.push_back(path.substr(from, dot - from));
    if (dot == std::string::npos) return out;
    from = dot + 1;
  }
}

std::optional<std::size_t> index_of(const std::string& segment) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(segment.data(), segment.data() + segment.size(), value);
  if (error != std::errc{} || end != segment.data() + segment.size()) return std::nullopt;
  return value;
}

// A copy built node by node: nodes made in code have no mark, whereas a parsed value would
// point at line 1 of a file it never was in.
YAML::Node without_marks(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      return YAML::Node(node.Scalar());
    case YAML::NodeType::Sequence: {
      YAML::Node out(YAML::NodeType::Sequence);
      for (const auto& each : node) out.push_back(without_marks(each));
      return out;
    }
    case YAML::NodeType::Map: {
      YAML::Node out(YAML::NodeType::Map);
      for (const auto& each : node) out[each.first.Scalar()] = without_marks(each.second);
      return out;
    }
    default:
      return YAML::Node(YAML::NodeType::Null);
  }
}

// A problem with the override itself, before the parser sees it.
[[noreturn]] void reject(const std::string& source_name, const field_override& o,
                         std::string message) {
  throw scenario_error({problem{source_name, 0, 0, o.path, "--set: " + std::move(message)}});
}

// Puts `value` at segments[k..] below `at` (reached by `walked`); '*' on a list puts it in
// every entry, so one key sets a field of every camera. Each place gets its own copy: yaml-cpp
// nodes are shared by reference, and a later override of one entry must not reach the others.
void put(YAML::Node at, const std::vector<std::string>& segments, std::size_t k,
         const YAML::Node& value, const std::string& walked, const std::string& source_name,
         const field_override& o) {
  const auto& segment = segments[k];
  const bool last = k + 1 == segments.size();
  const std::string here = walked + (walked.empty() ? "" : ".");
  if (segment == "*" || at.IsSequence()) {
    std::vector<std::size_t> entries;
    if (segment == "*") {
      if (!at.IsSequence() || at.size() == 0)
        reject(source_name, o,
               fmt::format("'*' stands for every entry of a list; {} is {}", walked,
                           at.IsSequence() ? "an empty list" : "not a list"));
      for (std::size_t index = 0; index < at.size(); ++index) entries.push_back(index);
    } else {
      const auto index = index_of(segment);
      if (!index || *index >= at.size())
        reject(source_name, o,
               fmt::format("{} is a list of {}; '{}' is not one of its indices (0 to {}, or *)",
                           walked, at.size(), segment, static_cast<long>(at.size()) - 1));
      entries.push_back(*index);
    }
    for (const auto index : entries) {
      if (last)
        at[index] = without_marks(value);
      else
        put(at[index], segments, k + 1, value, here + std::to_string(index), source_name, o);
    }
    return;
  }
  if (at.IsScalar()) {
    reject(source_name, o,
           fmt::format("{} is a value ('{}'), not a mapping with '{}' in it", walked, at.Scalar(),
                       segment));
  }
  if (!at.IsMap()) at = YAML::Node(YAML::NodeType::Map);
  if (last) {
    at[segment] = without_marks(value);
    return;
  }
  put(at[segment], segments, k + 1, value, here + segment, source_name, o);
}

void apply(YAML::Node& document, const field_override& o, const std::string& source_name) {
  for (const auto& text : {o.path, o.value}) {
    if (const auto bad = first_non_utf8(text)) reject(source_name, o, expected_utf8(*bad));
  }
  YAML::Node value;
  try {
    value = without_marks(YAML::Load(o.value));
  } catch (const YAML::Exception& error) {
    reject(source_name, o, fmt::format("'{}' is not a YAML value: {}", o.value, error.msg));
  }
  if (!document.IsMap()) document = YAML::Node(YAML::NodeType::Map);
  put(document, segments_of(o.path), 0, value, "", source_name, o);
}

}  // namespace

void apply_overrides(YAML::Node& document, std::span<const field_override> overrides,
                     const std::string& source_name) {
  for (const auto& each : overrides) apply(document, each, source_name);
}

}  // namespace argus::config
