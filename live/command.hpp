#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include "config/scenario.hpp"

namespace argus::live {

/// What the operator of a live run (`argus serve`) can ask for.
enum class command_kind { task, cancel, crash, recover, cut, heal };

/// The name of `kind` on the wire and in `commands.yaml` ("task", "cut", ...).
std::string_view name_of(command_kind kind) noexcept;

/// One operator command. Which fields count depends on `kind`:
/// - task: `camera` and `pixel` (the click in that camera's feed), `cameras_wanted`;
///   `task` is the index the task gets once it takes effect;
/// - cancel: `task`, the index of the task to end;
/// - crash, recover: `camera`;
/// - cut, heal: the link between `camera` and `peer`.
struct command {
  command_kind kind = command_kind::task;
  int camera = 0;
  int peer = 0;
  config::pixel_point pixel;
  unsigned cameras_wanted = 1;
  int task = -1;
  friend bool operator==(const command&, const command&) = default;
};

/// A command and the tick at which it took effect.
struct timed_command {
  std::int64_t tick = 0;
  command what;
  friend bool operator==(const timed_command&, const timed_command&) = default;
};

/// Whether `kind` is carried out by the scenario script (tasks) rather than the fault injector.
constexpr bool is_task_command(command_kind kind) noexcept {
  return kind == command_kind::task || kind == command_kind::cancel;
}

/// The scenario task a task command stands for, issued at `at`: the operator's click, as a
/// scenario's `pixel:` task (the same path live and in a replay).
config::operator_task operator_task_of(const command& c, config::seconds at);

/// Reads a command sent by the page, e.g. `{"command":"task","camera":7,"pixel":[160,120]}` or
/// `{"command":"cut","camera":1,"peer":2}`, and checks it against `scenario`: a camera that
/// exists, a pixel inside that camera's frame, a link that exists. Returns the command, or a
/// message saying what is wrong with it (for an HTTP 400). Whether a task can be cancelled is
/// only known at the tick the command would take effect (the scenario script decides).
std::variant<command, std::string> parse_command(std::string_view json,
                                                 const config::scenario& scenario);

}  // namespace argus::live
