#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "nlohmann/json.hpp"

namespace argus::report {

/// A run's events.jsonl: one JSON object per line, `{"t":..,"tick":..,"source":..,"kind":..}`
/// plus the fields of its kind (README, docs/protocol.md). Lines that do not parse (the last
/// one of a killed run) are skipped.
struct event_log {
  std::vector<nlohmann::json> events;

  /// Reads `file`; nothing when it does not exist.
  static std::optional<event_log> read(const std::filesystem::path& file);

  /// Parses JSON-lines text.
  static event_log parse(const std::string& text);

  /// The time of the last event, 0 when there is none.
  double last_time_s() const;
};

/// `field` of `event` as an integer, or `fallback` when it is absent or not a number.
long long integer_field(const nlohmann::json& event, const char* field, long long fallback = -1);

/// `field` of `event` as text, or "" when it is absent or not a string.
std::string text_field(const nlohmann::json& event, const char* field);

}  // namespace argus::report
