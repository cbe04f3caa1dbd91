#include "apps/task_option.hpp"

#include <yaml-cpp/yaml.h>

#include <array>
#include <fstream>
#include <sstream>

#include "CLI/CLI.hpp"
#include "config/scenario_loader.hpp"
#include "config/utf8_text.hpp"
#include "fmt/format.h"
#include "fmt/ranges.h"

namespace argus::apps {
namespace {

constexpr std::array<std::string_view, 8> task_keys{
    "at",          "camera",   "pedestrian", "pixel", "first_to_enter", "cameras_wanted",
    "max_cameras", "cancel_at"};

/// The YAML value `value` of the spec `text`; YAML that does not parse (`at=[`) is a
/// command-line error naming --task, like every other malformed spec.
YAML::Node task_value(const std::string& value, const std::string& text) {
  try {
    return YAML::Load(value);
  } catch (const YAML::Exception& e) {
    throw CLI::ValidationError("--task",
                               fmt::format("cannot read '{}' in '{}': {}", value, text, e.msg));
  }
}

YAML::Node task_node(const std::string& text) {
  if (const auto bad = config::first_non_utf8(text))
    throw CLI::ValidationError("--task",
                               fmt::format("{} of '{}'", config::expected_utf8(*bad), text));
  YAML::Node node(YAML::NodeType::Map);
  std::stringstream in(text);
  std::string pair;
  while (std::getline(in, pair, ',')) {
    const auto eq = pair.find('=');
    const auto key = pair.substr(0, eq);
    if (eq == std::string::npos || eq == 0 || eq + 1 == pair.size())
      throw CLI::ValidationError("--task",
                                 fmt::format("expected key=value pairs separated by commas, e.g. "
                                             "'at=10s,camera=7,pixel=160x120', got '{}'",
                                             text));
    if (std::find(task_keys.begin(), task_keys.end(), key) == task_keys.end())
      throw CLI::ValidationError("--task", fmt::format("unknown key '{}' in '{}' (keys: {})", key,
                                                       text, fmt::join(task_keys, ", ")));
    const auto value = pair.substr(eq + 1);
    if (key == "pixel") {
      const auto x = value.find_first_of("xX");
      if (x == std::string::npos)
        throw CLI::ValidationError(
            "--task", fmt::format("expected pixel=XxY, e.g. pixel=160x120, got '{}'", value));
      YAML::Node point(YAML::NodeType::Sequence);
      point.push_back(task_value(value.substr(0, x), text));
      point.push_back(task_value(value.substr(x + 1), text));
      node[key] = point;
    } else {
      node[key] = task_value(value, text);
    }
  }
  return node;
}

}  // namespace

config::scenario load_with_tasks(const std::string& file,
                                 std::span<const config::field_override> overrides,
                                 const std::vector<std::string>& tasks) {
  if (tasks.empty()) return config::load_scenario(file, overrides);
  std::vector<YAML::Node> added;
  for (const auto& t : tasks) added.push_back(task_node(t));
  // The file's own problems are reported against the file, as without --task.
  auto scenario = config::load_scenario(file, overrides);
  auto root = YAML::LoadFile(file);
  if (!root["tasks"] || root["tasks"].IsNull())
    root["tasks"] = YAML::Node(YAML::NodeType::Sequence);
  for (auto& n : added) root["tasks"].push_back(n);
  YAML::Emitter out;
  out << root;
  auto merged = config::parse_scenario(out.c_str(), file, overrides);
  merged.source_path = scenario.source_path;
  return merged;
}

}  // namespace argus::apps
