#include "config/yaml_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "config/duration.hpp"
#include "config/edit_distance.hpp"

namespace argus::config {

namespace {

/// yaml-cpp marks are 0-based and -1 when unknown; problems are 1-based and 0 when unknown.
int one_based(int position) {
  return position < 0 ? 0 : position + 1;
}

template <class Integer>
std::optional<Integer> parse_integer(std::string_view text) {
  Integer value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::string with_note(std::string_view note) {
  return note.empty() ? std::string{} : fmt::format(" ({})", note);
}

}  // namespace

yaml_reader::yaml_reader(std::string file) : file_(std::move(file)) {
  // nop
}

void yaml_reader::report(const YAML::Mark& where, std::string field, std::string message) {
  problems_.push_back(problem{file_, one_based(where.line), one_based(where.column),
                              std::move(field), std::move(message)});
}

void yaml_reader::report(const YAML::Node& where, std::string field, std::string message) {
  report(where.Mark(), std::move(field), std::move(message));
}

std::vector<problem> yaml_reader::take_problems() {
  std::stable_sort(problems_.begin(), problems_.end(), [](const problem& a, const problem& b) {
    return std::pair{a.line, a.column} < std::pair{b.line, b.column};
  });
  return std::move(problems_);
}

std::string yaml_reader::describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      return fmt::format("'{}'", node.Scalar());
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a mapping";
    default:
      return "nothing";
  }
}

std::string yaml_reader::out_of_range(std::string_view kind, const std::string& bounds_text,
                                      std::string_view note, std::string_view got) {
  return fmt::format("expected {} {}{}, got {}", kind, bounds_text, with_note(note), got);
}

bool yaml_reader::expect_list(const YAML::Node& node, const std::string& field) {
  if (node.IsSequence()) return true;
  if (!node.IsNull()) report(node, field, "expected a list, got " + describe(node));
  return false;
}

std::optional<std::string> yaml_reader::scalar(const YAML::Node& node, const std::string& field,
                                               std::string_view what) {
  if (node.IsScalar()) return node.Scalar();
  report(node, field, fmt::format("expected {}, got {}", what, describe(node)));
  return std::nullopt;
}

bool yaml_reader::read(const YAML::Node& node, const std::string& field, double& out,
                       const value_bounds& bounds, std::string_view note) {
  const auto text = scalar(node, field, "a number");
  if (!text) return false;
  double value = 0.0;
  std::string_view digits = *text;
  // from_chars takes no leading '+', YAML does.
  if (digits.starts_with('+')) digits.remove_prefix(1);
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || error != std::errc{} || end != digits.data() + digits.size() ||
      !std::isfinite(value)) {
    report(node, field, fmt::format("expected a number, got '{}'", *text));
    return false;
  }
  if (!bounds.contains(value)) {
    report(node, field, out_of_range("a number", bounds.describe(), note, *text));
    return false;
  }
  out = value;
  return true;
}

bool yaml_reader::read(const YAML::Node& node, const std::string& field, std::uint64_t& out,
                       const value_bounds& bounds) {
  const auto text = scalar(node, field, "a non-negative integer");
  if (!text) return false;
  const auto value = parse_integer<std::uint64_t>(*text);
  if (!value) {
    report(node, field, fmt::format("expected a non-negative integer, got '{}'", *text));
    return false;
  }
  if (!bounds.contains(static_cast<double>(*value))) {
    report(node, field, out_of_range("an integer", bounds.describe(), {}, *text));
    return false;
  }
  out = *value;
  return true;
}

bool yaml_reader::read(const YAML::Node& node, const std::string& field, unsigned& out,
                       const value_bounds& bounds) {
  std::uint64_t wide = 0;
  if (!read(node, field, wide, bounds)) return false;
  constexpr auto largest = std::numeric_limits<unsigned>::max();
  if (wide > largest) {
    report(
        node, field,
        out_of_range("an integer", value_bounds::at_most(largest).describe(), {}, node.Scalar()));
    return false;
  }
  out = static_cast<unsigned>(wide);
  return true;
}

bool yaml_reader::read(const YAML::Node& node, const std::string& field, int& out,
                       const value_bounds& bounds) {
  const auto text = scalar(node, field, "an integer");
  if (!text) return false;
  const auto value = parse_integer<int>(*text);
  if (!value) {
    report(node, field, fmt::format("expected an integer, got '{}'", *text));
    return false;
  }
  if (!bounds.contains(*value)) {
    report(node, field, out_of_range("an integer", bounds.describe(), {}, *text));
    return false;
  }
  out = *value;
  return true;
}

bool yaml_reader::read(const YAML::Node& node, const std::string& field, seconds& out,
                       const value_bounds& bounds, std::string_view note) {
  constexpr std::string_view expected = "a duration with a unit, e.g. '1500 ms'";
  const auto text = scalar(node, field, expected);
  if (!text) return false;
  const auto value = parse_duration(*text);
  if (!value) {
    report(node, field, fmt::format("expected {}, got '{}'", expected, *text));
    return false;
  }
  if (!bounds.contains(value->count())) {
    const auto bounds_text =
        bounds.describe([](double limit) { return format_duration(seconds{limit}); });
    report(node, field, out_of_range("a duration", bounds_text, note, *text));
    return false;
  }
  out = *value;
  return true;
}

bool yaml_reader::read(const YAML::Node& node, const std::string& field, bool& out) {
  const auto text = scalar(node, field, "true or false");
  if (!text) return false;
  bool value = false;
  if (!YAML::convert<bool>::decode(node, value)) {
    report(node, field, fmt::format("expected true or false, got '{}'", *text));
    return false;
  }
  out = value;
  return true;
}

bool yaml_reader::read(const YAML::Node& node, const std::string& field, std::string& out) {
  if (node.IsNull()) {
    out.clear();
    return true;
  }
  const auto text = scalar(node, field, "a string");
  if (!text) return false;
  out = *text;
  return true;
}

std::optional<std::size_t> yaml_reader::read_choice(const YAML::Node& node,
                                                    const std::string& field,
                                                    std::span<const std::string_view> names) {
  const auto listing = fmt::format("{}", fmt::join(names, ", "));
  const auto text = scalar(node, field, "one of: " + listing);
  if (!text) return std::nullopt;
  const auto found = std::find(names.begin(), names.end(), *text);
  if (found != names.end()) return static_cast<std::size_t>(found - names.begin());
  auto message = fmt::format("expected one of: {}, got '{}'", listing, *text);
  if (const auto hint = closest_match(*text, names)) {
    message += fmt::format("; did you mean '{}'?", *hint);
  }
  report(node, field, std::move(message));
  return std::nullopt;
}

}  // namespace argus::config
