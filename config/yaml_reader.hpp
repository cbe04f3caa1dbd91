#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "config/enum_names.hpp"
#include "config/scenario.hpp"
#include "config/scenario_error.hpp"
#include "config/value_bounds.hpp"

namespace argus::config {

/// Reads typed values out of one YAML document and collects a `problem` for each value that
/// does not fit, instead of throwing at the first one, so a single pass finds them all.
/// Internal to argus_config: its header needs yaml-cpp, which the library links privately.
///
/// Each `read` leaves `out` untouched and returns false when the value is wrong; the caller
/// does not need to care, because any problem makes the whole load fail.
class yaml_reader {
 public:
  /// `file` names the source in every problem.
  explicit yaml_reader(std::string file);

  /// Records a problem at `where` (yaml-cpp's 0-based mark; reported 1-based).
  void report(const YAML::Mark& where, std::string field, std::string message);

  /// Records a problem at the position of `where`.
  void report(const YAML::Node& where, std::string field, std::string message);

  /// Problems found so far, in the order found.
  const std::vector<problem>& problems() const noexcept { return problems_; }

  /// Hands over the problems, sorted by position in the file.
  std::vector<problem> take_problems();

  /// The node as a user would name it after "got": 'text', a mapping, a list or nothing.
  static std::string describe(const YAML::Node& node);

  /// "expected KIND BOUNDS (NOTE), got GOT": the message for a value outside its range.
  static std::string out_of_range(std::string_view kind, const std::string& bounds_text,
                                  std::string_view note, std::string_view got);

  /// Whether `node` is a list; reports "expected a list" otherwise. Null (`key:` with nothing
  /// after it) is an empty list and returns false silently.
  bool expect_list(const YAML::Node& node, const std::string& field);

  /// A finite number within `bounds`; `note` explains a bound taken from another field.
  bool read(const YAML::Node& node, const std::string& field, double& out,
            const value_bounds& bounds = {}, std::string_view note = {});
  /// A non-negative integer within `bounds`.
  bool read(const YAML::Node& node, const std::string& field, std::uint64_t& out,
            const value_bounds& bounds = {});
  /// A non-negative integer within `bounds` that fits `unsigned`.
  bool read(const YAML::Node& node, const std::string& field, unsigned& out,
            const value_bounds& bounds = {});
  /// An integer within `bounds` that fits `int`.
  bool read(const YAML::Node& node, const std::string& field, int& out,
            const value_bounds& bounds = {});
  /// A duration with a unit (see parse_duration) within `bounds` (in seconds).
  bool read(const YAML::Node& node, const std::string& field, seconds& out,
            const value_bounds& bounds = {}, std::string_view note = {});
  /// true/false (also yes/no, on/off).
  bool read(const YAML::Node& node, const std::string& field, bool& out);
  /// Any scalar as text; nothing (null) reads as the empty string.
  bool read(const YAML::Node& node, const std::string& field, std::string& out);

  /// One of the YAML names in `names`; returns its index.
  std::optional<std::size_t> read_choice(const YAML::Node& node, const std::string& field,
                                         std::span<const std::string_view> names);

  /// An enumerator by its YAML name (see enum_names.hpp).
  template <class Enum>
  requires std::is_enum_v<Enum>
  bool read(const YAML::Node& node, const std::string& field, Enum& out) {
    static constexpr auto names = yaml_names<Enum>();
    const auto index = read_choice(node, field, names);
    if (!index) return false;
    out = enum_names<Enum>::entries[*index].value;
    return true;
  }

 private:
  /// The scalar text of `node`, or a "expected WHAT, got ..." problem.
  std::optional<std::string> scalar(const YAML::Node& node, const std::string& field,
                                    std::string_view what);

  std::string file_;
  std::vector<problem> problems_;
};

}  // namespace argus::config
