#pragma once

#include "caf/fwd.hpp"

namespace argus::actors {

/// Spawns an actor that turns the clock's `(progress_atom, int64 tick, int64 end_tick,
/// double wall_seconds)` reports into one self-overwriting status line on stderr: simulated
/// time, speed ratio (virtual over wall seconds), ETA, and who carries each operator task (its
/// leader and how many members follow; the clock forwards the events that change groups as
/// `(record_atom, int64 tick, std::vector<sim_event>)`). Meant for terminals only; the caller
/// decides (isatty). Purely cosmetic: nothing it prints enters the event log.
caf::actor spawn_progress_printer(caf::actor_system& system, double tick_seconds);

}  // namespace argus::actors
