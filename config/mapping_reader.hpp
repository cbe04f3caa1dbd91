#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "config/yaml_reader.hpp"

namespace argus::config {

/// Reads one YAML mapping of a scenario: looks its keys up and rejects, on construction, every
/// key the schema does not know ("unknown key 'speeed' (expected one of: ...); did you mean
/// 'speed'?") and every key given twice. A null node (`run:` with nothing after it) reads as
/// an empty mapping, so every field keeps its default. Internal to argus_config.
class mapping_reader {
 public:
  /// Reads `node`, found at field path `path` ("" for the document, "cameras[2]", ...);
  /// `keys` lists the keys the schema allows there, in the order the schema shows them.
  mapping_reader(yaml_reader& reader, const YAML::Node& node, std::string path,
                 std::span<const std::string_view> keys);

  /// Whether the node was a mapping (or null); if not, a problem was reported and every key
  /// reads as absent.
  bool is_mapping() const noexcept { return is_mapping_; }

  /// The value under `key`, if present.
  std::optional<YAML::Node> find(std::string_view key) const;

  /// The full field path of `key`, e.g. "run.speed".
  std::string field(std::string_view key) const;

  /// Whether `key` is present; if not, reports "missing required key" (plus `why`, if
  /// given) at the position of this mapping.
  bool require(std::string_view key, std::string_view why = {});

  /// Reads the value under `key` into `out` if present (see yaml_reader::read for the extra
  /// arguments: bounds, note). Returns whether it was present and valid.
  template <class T, class... Extra>
  bool read(std::string_view key, T& out, Extra&&... extra) {
    const auto value = find(key);
    return value && reader_.read(*value, field(key), out, std::forward<Extra>(extra)...);
  }

  /// For a `key` left out: reports when its default `value` lies outside `bounds`, which
  /// happens when another field (a limit) moved the range away from the default.
  void check_default(std::string_view key, double value, const value_bounds& bounds,
                     std::string_view note);

  /// check_default for durations.
  void check_default(std::string_view key, seconds value, const value_bounds& bounds,
                     std::string_view note);

 private:
  yaml_reader& reader_;
  std::string path_;
  YAML::Mark mark_;
  bool is_mapping_ = false;
  /// One known key present in the mapping.
  struct entry {
    std::string key;
    YAML::Mark key_mark;
    YAML::Node value;
  };

  std::vector<entry> entries_;
};

}  // namespace argus::config
