#include "world/layout_loader.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "config/mapping_reader.hpp"
#include "config/utf8_text.hpp"
#include "config/yaml_guards.hpp"
#include "config/yaml_reader.hpp"

namespace argus::world {

const char* to_string(region_kind kind) noexcept {
  switch (kind) {
    case region_kind::concourse:
      return "concourse";
    case region_kind::waiting_room:
      return "waiting_room";
    case region_kind::arcade:
      return "arcade";
    case region_kind::platforms:
      return "platforms";
    case region_kind::tracks:
      return "tracks";
    case region_kind::other:
      return "other";
  }
  return "?";
}

const char* to_string(portal_kind kind) noexcept {
  return kind == portal_kind::street ? "street" : "internal";
}

namespace {

using config::mapping_reader;
using config::nul_byte;
using config::problem;
using config::refuse_stuck_documents;
using config::scenario_error;
using config::value_bounds;
using config::yaml_reader;

constexpr std::array<std::string_view, 11> layout_keys{
    "name",          "size_m",           "walls",   "obstacles", "regions",       "portals",
    "ticket_booths", "vending_machines", "benches", "stairs",    "meeting_points"};
constexpr std::array<std::string_view, 4> obstacle_keys{"name", "polygon", "min", "max"};
constexpr std::array<std::string_view, 5> region_keys{"name", "kind", "min", "max", "speed_factor"};
constexpr std::array<std::string_view, 4> portal_keys{"name", "kind", "min", "max"};
constexpr std::array<std::string_view, 9> counter_keys{"name",
                                                       "min",
                                                       "max",
                                                       "service_point",
                                                       "queue_direction",
                                                       "queue_spacing_m",
                                                       "max_queue_length",
                                                       "service_time_s",
                                                       "note"};
constexpr std::array<std::string_view, 5> bench_keys{"name", "from", "to", "seats", "facing"};
constexpr std::array<std::string_view, 3> stairs_keys{"name", "min", "max"};
constexpr std::array<std::string_view, 3> meeting_keys{"name", "position", "radius_m"};
constexpr std::array<std::string_view, 6> region_kind_names{"concourse", "waiting_room", "arcade",
                                                            "platforms", "tracks",       "other"};
constexpr std::array<std::string_view, 2> portal_kind_names{"street", "internal"};

std::string item(std::string_view path, std::size_t index) {
  return fmt::format("{}[{}]", path, index);
}

/// Reads one layout document; the one place that knows the layout schema.
class layout_parser {
 public:
  explicit layout_parser(yaml_reader& reader) : reader_(reader) {
    // nop
  }

  void parse(const YAML::Node& root, layout& out) {
    mapping_reader document(reader_, root, "", layout_keys);
    document.read("name", out.name);
    if (const auto node = document.find("size_m")) {
      if (auto size = read_point(*node, "size_m")) {
        if (size->x() <= 0.0 || size->y() <= 0.0) {
          reader_.report(*node, "size_m", "expected a positive width and height");
        } else {
          out.size_m = *size;
        }
      }
    }
    size_ = out.size_m;
    // Portals before the rest (regions look at them), but after size_m, which bounds them.
    if (auto node = document.find("portals")) read_portals(*node, out.portals);
    if (auto node = document.find("walls")) read_walls(*node, out.walls);
    if (auto node = document.find("obstacles")) read_obstacles(*node, out.obstacles);
    if (auto node = document.find("regions")) read_regions(*node, out);
    if (auto node = document.find("ticket_booths"))
      read_counters(*node, "ticket_booths", out.ticket_booths);
    if (auto node = document.find("vending_machines"))
      read_counters(*node, "vending_machines", out.vending_machines);
    if (auto node = document.find("benches")) read_benches(*node, out.benches);
    if (auto node = document.find("stairs")) read_stairs(*node, out.stairways);
    if (auto node = document.find("meeting_points")) read_meeting(*node, out.meeting_points);
    const bool has_street =
        std::any_of(out.portals.begin(), out.portals.end(),
                    [](const portal& p) { return p.kind == portal_kind::street; });
    if (reader_.problems().empty() && !has_street && out.stairways.empty()) {
      reader_.report(root, "portals",
                     "expected at least one street portal or stairs (pedestrians enter there)");
    }
    if (reader_.problems().empty() && out.regions.empty()) {
      reader_.report(root, "regions", "expected at least one walkable region");
    }
  }

 private:
  /// `[x, y]`, each finite; when `inside` also within the plan.
  std::optional<vec2> read_point(const YAML::Node& node, const std::string& field,
                                 bool inside = false) {
    if (!node.IsSequence() || node.size() != 2) {
      reader_.report(node, field, "expected a point [x, y], got " + yaml_reader::describe(node));
      return std::nullopt;
    }
    double x = 0.0;
    double y = 0.0;
    const auto bounds_x = inside ? value_bounds::closed(0.0, size_.x()) : value_bounds::any();
    const auto bounds_y = inside ? value_bounds::closed(0.0, size_.y()) : value_bounds::any();
    const bool ok_x =
        reader_.read(node[0], field + "[0]", x, bounds_x, inside ? "the plan's width" : "");
    const bool ok_y =
        reader_.read(node[1], field + "[1]", y, bounds_y, inside ? "the plan's height" : "");
    if (!ok_x || !ok_y) return std::nullopt;
    return vec2{x, y};
  }

  /// A unit direction: any non-zero vector, normalised.
  std::optional<vec2> read_direction(const YAML::Node& node, const std::string& field) {
    auto v = read_point(node, field);
    if (!v) return std::nullopt;
    if (v->norm() < 1e-9) {
      reader_.report(node, field, "expected a non-zero direction");
      return std::nullopt;
    }
    return v->normalized();
  }

  /// A box from keys `min` and `max` of `map`, with min < max on both axes, inside the plan.
  std::optional<box> read_box(mapping_reader& map, const YAML::Node& where) {
    const bool has_min = map.require("min");
    const bool has_max = map.require("max");
    if (!has_min || !has_max) return std::nullopt;
    auto low = read_point(*map.find("min"), map.field("min"), true);
    auto high = read_point(*map.find("max"), map.field("max"), true);
    if (!low || !high) return std::nullopt;
    if (low->x() >= high->x() || low->y() >= high->y()) {
      reader_.report(*map.find("max"), map.field("max"),
                     fmt::format("expected max > min on both axes, got min [{}, {}], max [{}, {}]",
                                 low->x(), low->y(), high->x(), high->y()));
      return std::nullopt;
    }
    (void)where;
    return box{*low, *high};
  }

  void require_name(mapping_reader& map, const YAML::Node& node, std::string& out,
                    const std::string& path) {
    if (!map.require("name")) return;
    map.read("name", out);
    if (out.empty()) {
      reader_.report(node, path + ".name", "expected a non-empty name");
      return;
    }
    if (!names_.insert(out).second) {
      reader_.report(*map.find("name"), path + ".name",
                     fmt::format("duplicate name '{}' (names must be unique)", out));
    }
  }

  void read_walls(const YAML::Node& node, std::vector<wall>& out) {
    if (!reader_.expect_list(node, "walls")) return;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const auto path = item("walls", i);
      const auto& line = node[i];
      if (!line.IsSequence() || line.size() < 2) {
        reader_.report(
            line, path,
            "expected a polyline of at least two points, got " + yaml_reader::describe(line));
        continue;
      }
      wall w;
      for (std::size_t k = 0; k < line.size(); ++k) {
        if (auto p = read_point(line[k], item(path, k), true)) w.points.push_back(*p);
      }
      if (w.points.size() == line.size()) out.push_back(std::move(w));
    }
  }

  void read_obstacles(const YAML::Node& node, std::vector<obstacle>& out) {
    if (!reader_.expect_list(node, "obstacles")) return;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const auto path = item("obstacles", i);
      mapping_reader map(reader_, node[i], path, obstacle_keys);
      if (!map.is_mapping()) continue;
      obstacle o;
      map.read("name", o.name);
      if (const auto polygon = map.find("polygon")) {
        if (map.find("min") || map.find("max")) {
          reader_.report(*polygon, map.field("polygon"),
                         "expected either polygon or min/max, not both");
          continue;
        }
        if (!polygon->IsSequence() || polygon->size() < 3) {
          reader_.report(*polygon, map.field("polygon"),
                         "expected a polygon of at least three points, got " +
                             yaml_reader::describe(*polygon));
          continue;
        }
        for (std::size_t k = 0; k < polygon->size(); ++k) {
          if (auto p = read_point((*polygon)[k], item(map.field("polygon"), k), true)) {
            o.polygon.push_back(*p);
          }
        }
        if (o.polygon.size() == polygon->size()) out.push_back(std::move(o));
      } else if (auto b = read_box(map, node[i])) {
        o.polygon = {b->min, {b->max.x(), b->min.y()}, b->max, {b->min.x(), b->max.y()}};
        out.push_back(std::move(o));
      }
    }
  }

  void read_regions(const YAML::Node& node, layout& out) {
    if (!reader_.expect_list(node, "regions")) return;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const auto path = item("regions", i);
      mapping_reader map(reader_, node[i], path, region_keys);
      if (!map.is_mapping()) continue;
      region r;
      require_name(map, node[i], r.name, path);
      if (map.require("kind")) {
        if (auto index =
                reader_.read_choice(*map.find("kind"), map.field("kind"), region_kind_names)) {
          r.kind = static_cast<region_kind>(*index);
        }
      }
      if (auto b = read_box(map, node[i])) r.area = *b;
      map.read("speed_factor", r.speed_factor, value_bounds::closed(0.1, 1.5));
      out.regions.push_back(std::move(r));
    }
  }

 public:
  void read_portals(const YAML::Node& node, std::vector<portal>& out) {
    if (!reader_.expect_list(node, "portals")) return;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const auto path = item("portals", i);
      mapping_reader map(reader_, node[i], path, portal_keys);
      if (!map.is_mapping()) continue;
      portal p;
      require_name(map, node[i], p.name, path);
      if (map.require("kind")) {
        if (auto index =
                reader_.read_choice(*map.find("kind"), map.field("kind"), portal_kind_names)) {
          p.kind = static_cast<portal_kind>(*index);
        }
      }
      if (auto b = read_box(map, node[i])) p.area = *b;
      out.push_back(std::move(p));
    }
  }

 private:
  void read_counters(const YAML::Node& node, const std::string& list,
                     std::vector<service_counter>& out) {
    if (!reader_.expect_list(node, list)) return;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const auto path = item(list, i);
      mapping_reader map(reader_, node[i], path, counter_keys);
      if (!map.is_mapping()) continue;
      service_counter c;
      require_name(map, node[i], c.name, path);
      if (auto b = read_box(map, node[i])) c.footprint = *b;
      if (map.require("service_point")) {
        if (auto p = read_point(*map.find("service_point"), map.field("service_point"), true)) {
          c.service_point = *p;
          if (c.footprint.contains(*p)) {
            reader_.report(*map.find("service_point"), map.field("service_point"),
                           "expected a point outside the footprint (the customer stands there)");
          }
        }
      }
      if (const auto dir = map.find("queue_direction")) {
        if (auto d = read_direction(*dir, map.field("queue_direction"))) c.queue_direction = *d;
      }
      map.read("queue_spacing_m", c.queue_spacing_m, value_bounds::closed(0.6, 3.0));
      map.read("max_queue_length", c.max_queue_length, value_bounds::closed(1, 100));
      if (const auto times = map.find("service_time_s")) {
        if (auto t = read_point(*times, map.field("service_time_s"))) {
          if (t->x() < 0.0 || t->y() < t->x()) {
            reader_.report(*times, map.field("service_time_s"),
                           "expected [min, max] seconds with 0 <= min <= max");
          } else {
            c.min_service_s = t->x();
            c.max_service_s = t->y();
          }
        }
      }
      out.push_back(std::move(c));
    }
  }

  void read_benches(const YAML::Node& node, std::vector<bench>& out) {
    if (!reader_.expect_list(node, "benches")) return;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const auto path = item("benches", i);
      mapping_reader map(reader_, node[i], path, bench_keys);
      if (!map.is_mapping()) continue;
      bench b;
      require_name(map, node[i], b.name, path);
      std::optional<vec2> from;
      std::optional<vec2> to;
      if (map.require("from")) from = read_point(*map.find("from"), map.field("from"), true);
      if (map.require("to")) to = read_point(*map.find("to"), map.field("to"), true);
      if (map.require("seats")) map.read("seats", b.seats, value_bounds::closed(1, 100));
      if (const auto facing = map.find("facing")) {
        if (auto d = read_direction(*facing, map.field("facing"))) b.facing = *d;
      }
      if (from && to) {
        b.from = *from;
        b.to = *to;
        const double length = (*to - *from).norm();
        // Seats closer than a shoulder width would make sitters overlap.
        if (length < 0.7 * b.seats) {
          reader_.report(*map.find("to"), map.field("to"),
                         fmt::format("expected a bench at least 0.7 m per seat long ({} m for {} "
                                     "seats), got {} m",
                                     0.7 * b.seats, b.seats, length));
        }
      }
      out.push_back(std::move(b));
    }
  }

  void read_stairs(const YAML::Node& node, std::vector<stairs>& out) {
    if (!reader_.expect_list(node, "stairs")) return;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const auto path = item("stairs", i);
      mapping_reader map(reader_, node[i], path, stairs_keys);
      if (!map.is_mapping()) continue;
      stairs s;
      require_name(map, node[i], s.name, path);
      if (auto b = read_box(map, node[i])) s.area = *b;
      out.push_back(std::move(s));
    }
  }

  void read_meeting(const YAML::Node& node, std::vector<meeting_point>& out) {
    if (!reader_.expect_list(node, "meeting_points")) return;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const auto path = item("meeting_points", i);
      mapping_reader map(reader_, node[i], path, meeting_keys);
      if (!map.is_mapping()) continue;
      meeting_point m;
      require_name(map, node[i], m.name, path);
      if (map.require("position")) {
        if (auto p = read_point(*map.find("position"), map.field("position"), true))
          m.position = *p;
      }
      map.read("radius_m", m.radius_m, value_bounds::closed(0.0, 20.0));
      out.push_back(std::move(m));
    }
  }

  yaml_reader& reader_;
  vec2 size_{200.0, 100.0};
  std::set<std::string> names_;
};

}  // namespace

layout parse_layout(std::string_view yaml_text, const std::string& source_name) {
  if (const auto bad = config::first_non_utf8(yaml_text))
    throw scenario_error({config::not_utf8(source_name, *bad)});
  if (auto nul = nul_byte(source_name, yaml_text)) throw scenario_error({std::move(*nul)});
  std::vector<YAML::Node> documents;
  try {
    const std::string text{yaml_text};
    refuse_stuck_documents(text);
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& error) {
    throw scenario_error(
        {problem{source_name, error.mark.line + 1, error.mark.column + 1, {}, error.msg}});
  }
  if (documents.size() > 1) {
    throw scenario_error(
        {problem{source_name,
                 documents[1].Mark().line + 1,
                 1,
                 {},
                 fmt::format("expected one YAML document, got {}", documents.size())}});
  }
  layout out;
  out.name = std::filesystem::path{source_name}.stem().string();
  out.source_path = source_name;
  yaml_reader reader(source_name);
  layout_parser parser(reader);
  const YAML::Node root = documents.empty() ? YAML::Node{} : documents.front();
  parser.parse(root, out);
  if (!reader.problems().empty()) throw scenario_error(reader.take_problems());
  return out;
}

layout load_layout(const std::filesystem::path& file) {
  const auto name = file.string();
  std::ifstream stream(file, std::ios::binary);
  if (!stream || std::filesystem::is_directory(file)) {
    const int error = std::filesystem::is_directory(file) ? EISDIR : errno;
    throw scenario_error(
        {problem{name, 0, 0, {}, fmt::format("cannot open file: {}", std::strerror(error))}});
  }
  std::ostringstream text;
  text << stream.rdbuf();
  return parse_layout(text.str(), name);
}

std::filesystem::path builtin_layout_path() {
  return std::filesystem::path{ARGUS_SOURCE_DIR} / "scenarios" / "stations" /
         "penn_station_layout.yaml";
}

std::filesystem::path layout_path(const config::scenario& scenario) {
  if (scenario.world.layout.empty()) return builtin_layout_path();
  const std::filesystem::path layout{scenario.world.layout};
  if (layout.is_absolute() || scenario.source_path.empty()) return layout;
  return std::filesystem::path{scenario.source_path}.parent_path() / layout;
}

}  // namespace argus::world
