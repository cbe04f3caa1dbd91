#include "events/event.hpp"

#include <functional>
#include <map>

#include "nlohmann/json.hpp"

namespace argus::events {
namespace {

struct namer {
  std::string_view operator()(const demotion_sent& e) const { return e.step; }
  std::string_view operator()(const neighbour_change& e) const {
    return e.up ? "neighbour_up" : "neighbour_lost";
  }
  std::string_view operator()(const member_change& e) const {
    return e.added ? "member_added" : "member_dropped";
  }
  std::string_view operator()(const pedestrian_moved& e) const {
    return e.entered ? "pedestrian_entered" : "pedestrian_left";
  }
  std::string_view operator()(const custom& e) const { return e.kind; }
  template <class E>
  std::string_view operator()(const E&) const {
    return E::name;
  }
};

template <class Json>
using reader = std::function<std::optional<event>(const Json&)>;
template <class Json>
using reader_table = std::map<std::string, reader<Json>, std::less<>>;

// Reads a line as E, then `set` gives the kind's variant (e.g. neighbour_lost's `up`).
template <class E, class Json>
reader<Json> read_as(std::function<void(E&)> set = {}) {
  return [set](const Json& j) -> std::optional<event> {
    auto e = read_members<E>(j);
    if (!e) return std::nullopt;
    if (set) set(*e);
    return event{std::move(*e)};
  };
}

template <class Json, class... E>
void add_all(reader_table<Json>& readers, std::variant<E...>*) {
  (
      [&] {
        if constexpr (!std::is_same_v<E, custom>)
          readers.emplace(std::string(E::name), read_as<E, Json>());
      }(),
      ...);
}

// One table per JSON type: a line already parsed is read as it is.
template <class Json>
const reader_table<Json>& readers() {
  static const auto table = [] {
    reader_table<Json> r;
    add_all<Json>(r, static_cast<event*>(nullptr));
    for (const char* step : {"demoteack", "demotenack", "demoteretry"})
      r.emplace(step, read_as<demotion_sent, Json>([step](demotion_sent& e) { e.step = step; }));
    r.insert_or_assign("neighbour_lost",
                       read_as<neighbour_change, Json>([](neighbour_change& e) { e.up = false; }));
    r.insert_or_assign("member_dropped",
                       read_as<member_change, Json>([](member_change& e) { e.added = false; }));
    r.insert_or_assign("pedestrian_left", read_as<pedestrian_moved, Json>(
                                              [](pedestrian_moved& e) { e.entered = false; }));
    return r;
  }();
  return table;
}

}  // namespace

std::string_view kind_of(const event& e) {
  return std::visit(namer{}, e);
}

std::string fields_json(const event& e) {
  return std::visit(
      [](const auto& x) -> std::string {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, custom>)
          return x.fields_json;
        else
          return fields_of(x);
      },
      e);
}

std::optional<event> parse(const nlohmann::json& line) {
  if (!line.is_object()) return std::nullopt;
  const auto kind = line.find("kind");
  if (kind == line.end() || !kind->is_string()) return std::nullopt;
  const auto& name = kind->get_ref<const std::string&>();
  const auto& table = readers<nlohmann::json>();
  if (auto it = table.find(name); it != table.end()) return it->second(line);
  // Not ours: its members are the line's but the common four.
  auto members = line;
  for (const char* common : {"t", "tick", "source", "kind"}) members.erase(common);
  auto text = members.dump();
  return event{custom{name, text.substr(1, text.size() - 2)}};
}

std::optional<event> parse(std::string_view kind, std::string_view fields_json) {
  const auto& table = readers<nlohmann::ordered_json>();
  auto it = table.find(kind);
  if (it == table.end()) return event{custom{std::string(kind), std::string(fields_json)}};
  const auto j =
      nlohmann::ordered_json::parse("{" + std::string(fields_json) + "}", nullptr, false);
  if (j.is_discarded()) return std::nullopt;
  return it->second(j);
}

}  // namespace argus::events
