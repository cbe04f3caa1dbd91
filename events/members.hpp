#pragma once

// How an event's members are written to and read from events.jsonl (docs/events.md, "Common
// members"): each member type has one written form, so an event struct's member list fixes its
// line byte for byte. Hand-formatted as before the vocabulary existed: names in the struct's
// order, no spaces, strings unescaped identifiers (json_text is the one escaped string).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "fmt/format.h"
#include "nlohmann/json.hpp"

namespace argus::events {

/// A number written with exactly N decimals (docs/events.md `num(N)`).
template <int N>
struct fixed {
  double value = 0.0;
  fixed() = default;
  fixed(double v) : value(v) {}  // NOLINT: an event member is given as a plain double
  operator double() const { return value; }
  friend bool operator==(const fixed&, const fixed&) = default;
};

/// Free text, written as an escaped JSON string (an exception's message).
struct json_text {
  std::string text;
  friend bool operator==(const json_text&, const json_text&) = default;
};

/// An object of task ids to counts (`minima` of csp_solved): `{"3":1,"4":2}`.
using task_counts = std::vector<std::pair<std::uint32_t, unsigned>>;

namespace detail {

template <class T>
struct is_fixed : std::false_type {};
template <int N>
struct is_fixed<fixed<N>> : std::true_type {
  static constexpr int decimals = N;
};
template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};
template <class T>
struct is_vector : std::false_type {};
template <class T>
struct is_vector<std::vector<T>> : std::true_type {};

template <class T>
void write_value(std::string& out, const T& v) {
  if constexpr (std::is_same_v<T, bool>) {
    out += v ? "true" : "false";
  } else if constexpr (std::is_same_v<T, std::string>) {
    out += '"';
    out += v;
    out += '"';
  } else if constexpr (std::is_same_v<T, json_text>) {
    out += nlohmann::json(v.text).dump();
  } else if constexpr (is_fixed<T>::value) {
    out += fmt::format("{:.{}f}", v.value, is_fixed<T>::decimals);
  } else if constexpr (std::is_same_v<T, task_counts>) {
    out += '{';
    for (std::size_t i = 0; i < v.size(); ++i)
      out += fmt::format(R"({}"{}":{})", i == 0 ? "" : ",", v[i].first, v[i].second);
    out += '}';
  } else if constexpr (is_vector<T>::value) {
    out += '[';
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i != 0) out += ',';
      write_value(out, v[i]);
    }
    out += ']';
  } else {
    static_assert(std::is_arithmetic_v<T>, "an event member of a type with no written form");
    out += fmt::format("{}", v);
  }
}

template <class Json, class T>
bool read_value(const Json& j, T& v) {
  if constexpr (std::is_same_v<T, bool>) {
    if (!j.is_boolean()) return false;
    v = j.template get<bool>();
  } else if constexpr (std::is_same_v<T, std::string>) {
    if (!j.is_string()) return false;
    v = j.template get<std::string>();
  } else if constexpr (std::is_same_v<T, json_text>) {
    if (!j.is_string()) return false;
    v.text = j.template get<std::string>();
  } else if constexpr (is_fixed<T>::value) {
    if (!j.is_number()) return false;
    v.value = j.template get<double>();
  } else if constexpr (std::is_same_v<T, task_counts>) {
    if (!j.is_object()) return false;
    v.clear();
    for (const auto& [key, count] : j.items()) {
      if (!count.is_number_unsigned()) return false;
      v.emplace_back(static_cast<std::uint32_t>(std::stoul(key)), count.template get<unsigned>());
    }
  } else if constexpr (is_vector<T>::value) {
    if (!j.is_array()) return false;
    v.clear();
    for (const auto& item : j) {
      typename T::value_type x{};
      if (!read_value(item, x)) return false;
      v.push_back(std::move(x));
    }
  } else {
    if (!j.is_number()) return false;
    v = j.template get<T>();
  }
  return true;
}

}  // namespace detail

/// The members of `e` as written after the common ones (JSON members without braces).
template <class Event>
std::string fields_of(const Event& e) {
  std::string out;
  const_cast<Event&>(e).members([&out](std::string_view name, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (detail::is_optional<T>::value) {
      if (!value) return;
      if (!out.empty()) out += ',';
      out += fmt::format(R"("{}":)", name);
      detail::write_value(out, *value);
    } else {
      if (!out.empty()) out += ',';
      out += fmt::format(R"("{}":)", name);
      detail::write_value(out, value);
    }
  });
  return out;
}

/// `Event` read from a line's JSON object; nothing when a member is of another type. A member
/// the line lacks keeps its default (a hand-made log, or one of an older version).
/// (Json: nlohmann::json, or nlohmann::ordered_json to keep an object member's order.)
template <class Event, class Json>
std::optional<Event> read_members(const Json& line) {
  Event e;
  bool ok = true;
  e.members([&](std::string_view name, auto& value) {
    using T = std::decay_t<decltype(value)>;
    const auto it = line.find(std::string(name));
    if (it == line.end()) return;
    if constexpr (detail::is_optional<T>::value) {
      typename T::value_type v{};
      if (!detail::read_value(*it, v)) ok = false;
      value = std::move(v);
    } else {
      if (!detail::read_value(*it, value)) ok = false;
    }
  });
  if (!ok) return std::nullopt;
  return e;
}

}  // namespace argus::events
