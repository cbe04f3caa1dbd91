#pragma once

#include "actors/pacing.hpp"
#include "config/scenario.hpp"
#include "live/command_log.hpp"
#include "live/command_queue.hpp"
#include "live/console_state.hpp"

namespace argus::live {

/// Everything a live run (`argus serve`) shares between the simulation and the server: the
/// operator's commands on their way in and as carried out, the pacing, and what the page shows.
struct session {
  /// For a run of `scenario`, starting at `speed`.
  session(const config::scenario& scenario, double speed) : pace(speed), console(scenario) {}

  command_queue queue;
  command_log log;
  actors::pacing pace;
  console_state console;
};

}  // namespace argus::live
