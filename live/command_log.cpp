#include "live/command_log.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <stdexcept>

#include "config/ticks.hpp"
#include "fmt/format.h"
#include "protocol/topology.hpp"

namespace argus::live {
namespace {

command_kind kind_named(const std::string& name, const std::string& where) {
  for (auto kind : {command_kind::task, command_kind::cancel, command_kind::crash,
                    command_kind::recover, command_kind::cut, command_kind::heal})
    if (name_of(kind) == name) return kind;
  throw std::runtime_error(fmt::format("{}: unknown command '{}'", where, name));
}

bool has_camera(const config::scenario& s, int id) {
  return std::any_of(s.cameras.begin(), s.cameras.end(), [&](const auto& c) { return c.id == id; });
}

}  // namespace

std::vector<timed_command> command_log::commands() const {
  std::vector<timed_command> out;
  {
    std::lock_guard<std::mutex> guard(mutex_);
    out = entries_;
  }
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    const bool a_task = is_task_command(a.what.kind);
    const bool b_task = is_task_command(b.what.kind);
    return a.tick != b.tick ? a.tick < b.tick : (a_task && !b_task);
  });
  return out;
}

std::string commands_yaml(std::span<const timed_command> commands, const config::scenario& run) {
  std::string out =
      "# The operator's commands of a live run (argus serve), each at the tick it took effect.\n"
      "# Replay: argus run SCENARIO --commands THIS_FILE (same seed and settings).\n";
  out += fmt::format("scenario: \"{}\"\nseed: {}\n", run.name, run.run.seed);
  if (commands.empty()) return out + "commands: []\n";
  out += "commands:\n";
  for (const auto& [tick, c] : commands) {
    out += fmt::format("  - {{tick: {}, command: {}", tick, name_of(c.kind));
    switch (c.kind) {
      case command_kind::task:
        out += fmt::format(", task: {}, camera: {}, pixel: [{}, {}], cameras_wanted: {}", c.task,
                           c.camera, c.pixel.x_px, c.pixel.y_px, c.cameras_wanted);
        break;
      case command_kind::cancel:
        out += fmt::format(", task: {}", c.task);
        break;
      case command_kind::crash:
      case command_kind::recover:
        out += fmt::format(", camera: {}", c.camera);
        break;
      case command_kind::cut:
      case command_kind::heal:
        out += fmt::format(", camera: {}, peer: {}", c.camera, c.peer);
        break;
    }
    out += "}\n";
  }
  return out;
}

std::vector<timed_command> read_commands(const std::filesystem::path& file) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(fmt::format("{}: {}", file.string(), e.what()));
  }
  const auto list = root.IsMap() ? root["commands"] : YAML::Node{};
  if (!list || !list.IsSequence())
    throw std::runtime_error(fmt::format("{}: expected a list under 'commands'", file.string()));
  std::vector<timed_command> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const auto where = fmt::format("{}: commands[{}]", file.string(), i);
    const auto& n = list[i];
    try {
      timed_command t;
      t.tick = n["tick"].as<std::int64_t>();
      if (t.tick < 0) throw std::runtime_error(where + ": tick must not be negative");
      t.what.kind = kind_named(n["command"].as<std::string>(), where);
      if (n["camera"]) t.what.camera = n["camera"].as<int>();
      if (n["peer"]) t.what.peer = n["peer"].as<int>();
      if (n["task"]) t.what.task = n["task"].as<int>();
      if (n["cameras_wanted"]) t.what.cameras_wanted = n["cameras_wanted"].as<unsigned>();
      if (n["pixel"]) {
        if (!n["pixel"].IsSequence() || n["pixel"].size() != 2)
          throw std::runtime_error(where + ": pixel must be [x, y]");
        t.what.pixel.x_px = n["pixel"][0].as<double>();
        t.what.pixel.y_px = n["pixel"][1].as<double>();
      }
      out.push_back(t);
    } catch (const YAML::Exception& e) {
      throw std::runtime_error(fmt::format("{}: {}", where, e.what()));
    }
  }
  return out;
}

void apply_commands(config::scenario& s, std::span<const timed_command> commands) {
  const protocol::topology topo(s);
  for (const auto& [tick, c] : commands) {
    const auto at = config::to_seconds(tick, s.run.tick);
    const auto where = fmt::format("command '{}' at tick {}", name_of(c.kind), tick);
    if (c.kind != command_kind::cancel && !has_camera(s, c.camera))
      throw std::invalid_argument(fmt::format("{}: unknown camera {}", where, c.camera));
    config::fault f;
    f.at = at;
    f.camera = c.camera;
    switch (c.kind) {
      case command_kind::task: {
        if (c.task != static_cast<int>(s.tasks.size()))
          throw std::invalid_argument(
              fmt::format("{}: task {} does not follow the scenario's {} tasks", where, c.task,
                          s.tasks.size()));
        s.tasks.push_back(operator_task_of(c, at));
        continue;
      }
      case command_kind::cancel: {
        if (c.task < 0 || c.task >= static_cast<int>(s.tasks.size()))
          throw std::invalid_argument(fmt::format("{}: no task {}", where, c.task));
        auto& t = s.tasks[static_cast<std::size_t>(c.task)];
        if (t.cancel_at)
          throw std::invalid_argument(
              fmt::format("{}: task {} is already cancelled", where, c.task));
        t.cancel_at = at;
        continue;
      }
      case command_kind::crash:
        f.kind = config::fault_kind::crash;
        break;
      case command_kind::recover:
        f.kind = config::fault_kind::recover;
        break;
      case command_kind::cut:
      case command_kind::heal: {
        const auto& near = topo.neighbours(c.camera);
        if (std::find(near.begin(), near.end(), c.peer) == near.end())
          throw std::invalid_argument(
              fmt::format("{}: no link between camera {} and camera {}", where, c.camera, c.peer));
        f.kind = c.kind == command_kind::cut ? config::fault_kind::link_cut
                                             : config::fault_kind::link_heal;
        f.peer = c.peer;
        break;
      }
    }
    s.faults.push_back(f);
  }
}

}  // namespace argus::live
