#pragma once

#include <cstdint>
#include <string_view>

#include "world/pedestrian.hpp"

namespace argus::world {

/// What happened to a pedestrian during a tick (for the recorder and the tests).
enum class event_kind : std::uint8_t {
  spawned,           ///< entered (resource: portal index, or -1 - stairs index for stairs)
  left,              ///< left the station (resource as for spawned)
  goal_started,      ///< began pursuing `goal`
  goal_completed,    ///< finished `goal`
  goal_abandoned,    ///< gave `goal` up (line full, no free seat, or no progress for long)
  joined_queue,      ///< joined the line of counter `resource`
  service_started,   ///< reached the head of counter `resource` and is being served
  service_finished,  ///< was served at counter `resource` and leaves the line
  sat_down,          ///< sat on seat `resource`
  stood_up,          ///< left seat `resource`
};

/// The name of an event kind ("service_started").
std::string_view to_string(event_kind kind) noexcept;

/// One event.
struct event {
  std::uint64_t tick = 0;
  int pedestrian = 0;
  event_kind kind = event_kind::spawned;
  goal_kind goal = goal_kind::go_to_platform;
  int resource = -1;
  friend bool operator==(const event&, const event&) = default;
};

}  // namespace argus::world
