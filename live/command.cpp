#include "live/command.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "fmt/format.h"
#include "nlohmann/json.hpp"
#include "protocol/topology.hpp"

namespace argus::live {
namespace {

constexpr std::array<std::pair<command_kind, std::string_view>, 6> names{{
    {command_kind::task, "task"},
    {command_kind::cancel, "cancel"},
    {command_kind::crash, "crash"},
    {command_kind::recover, "recover"},
    {command_kind::cut, "cut"},
    {command_kind::heal, "heal"},
}};

// A whole number in [low, high] under `key`, or a message.
std::variant<long long, std::string> integer_field(const nlohmann::json& j, const char* key,
                                                   long long low, long long high) {
  const auto it = j.find(key);
  if (it == j.end()) return fmt::format("'{}' is missing", key);
  if (!it->is_number_integer())
    return fmt::format("'{}' must be a whole number, got {}", key, it->dump());
  const auto value = it->get<long long>();
  if (value < low || value > high)
    return fmt::format("'{}' must be in [{}, {}], got {}", key, low, high, value);
  return value;
}

const config::camera_settings* find_camera(const config::scenario& s, long long id) {
  const auto it =
      std::find_if(s.cameras.begin(), s.cameras.end(), [&](const auto& c) { return c.id == id; });
  return it == s.cameras.end() ? nullptr : &*it;
}

}  // namespace

std::string_view name_of(command_kind kind) noexcept {
  for (const auto& [k, name] : names)
    if (k == kind) return name;
  return "?";
}

std::variant<command, std::string> parse_command(std::string_view json,
                                                 const config::scenario& scenario) {
  const auto j = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return std::string("malformed JSON");
  if (!j.is_object()) return std::string("expected a JSON object");
  const auto name = j.find("command");
  if (name == j.end() || !name->is_string())
    return std::string("'command' is missing (task, cancel, crash, recover, cut or heal)");
  command out;
  const auto wanted = name->get<std::string>();
  const auto known =
      std::find_if(names.begin(), names.end(), [&](const auto& n) { return n.second == wanted; });
  if (known == names.end())
    return fmt::format("unknown command '{}' (task, cancel, crash, recover, cut or heal)", wanted);
  out.kind = known->first;
  if (out.kind == command_kind::cancel) {
    auto task = integer_field(j, "task", 0, 1'000'000);
    if (auto* error = std::get_if<std::string>(&task)) return std::move(*error);
    out.task = static_cast<int>(std::get<long long>(task));
    return out;
  }
  auto camera = integer_field(j, "camera", INT32_MIN, INT32_MAX);
  if (auto* error = std::get_if<std::string>(&camera)) return std::move(*error);
  const auto* cam = find_camera(scenario, std::get<long long>(camera));
  if (cam == nullptr) return fmt::format("unknown camera {}", std::get<long long>(camera));
  out.camera = cam->id;
  if (out.kind == command_kind::cut || out.kind == command_kind::heal) {
    auto peer = integer_field(j, "peer", INT32_MIN, INT32_MAX);
    if (auto* error = std::get_if<std::string>(&peer)) return std::move(*error);
    out.peer = static_cast<int>(std::get<long long>(peer));
    const protocol::topology topo(scenario);
    const auto& near = topo.neighbours(out.camera);
    if (std::find(near.begin(), near.end(), out.peer) == near.end())
      return fmt::format("no link between camera {} and camera {}", out.camera, out.peer);
  }
  if (out.kind == command_kind::task) {
    const auto pixel = j.find("pixel");
    if (pixel == j.end() || !pixel->is_array() || pixel->size() != 2 || !(*pixel)[0].is_number() ||
        !(*pixel)[1].is_number())
      return std::string("'pixel' must be [x, y], a pixel in the camera's frame");
    const double x = (*pixel)[0].get<double>();
    const double y = (*pixel)[1].get<double>();
    const double width = cam->imaging.width_px;
    const double height = cam->imaging.height_px;
    if (!std::isfinite(x) || !std::isfinite(y) || x < 0.0 || x >= width || y < 0.0 || y >= height)
      return fmt::format("pixel [{}, {}] is outside camera {}'s {}x{} frame", x, y, cam->id, width,
                         height);
    out.pixel.x_px = x;
    out.pixel.y_px = y;
    if (j.contains("cameras_wanted")) {
      auto count = integer_field(j, "cameras_wanted", 1, 64);
      if (auto* error = std::get_if<std::string>(&count)) return std::move(*error);
      out.cameras_wanted = static_cast<unsigned>(std::get<long long>(count));
    }
  }
  return out;
}

config::operator_task operator_task_of(const command& c, config::seconds at) {
  config::operator_task t;
  t.at = at;
  t.camera = c.camera;
  t.by = config::task_target::pixel;
  t.pixel = c.pixel;
  t.cameras_wanted = c.cameras_wanted;
  return t;
}

}  // namespace argus::live
