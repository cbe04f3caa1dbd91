#pragma once

#include <cstdint>
#include <string>

#include "actors/phase.hpp"

namespace argus::actors {

/// When the clock ticks a participant.
enum class wake_mode : std::uint8_t {
  every_tick = 0,  ///< in its phase of every tick (cameras that sense each frame)
  on_demand = 1,   ///< only when it asked for a tick, or someone sent it mail
  never = 2,       ///< works on its mail alone (links); takes part in the end-of-run reports
};

/// What a participant tells the clock when it joins. The id is stable across runs (derived
/// from the scenario, not from spawn order) and orders everything canonically.
struct participant_info {
  std::uint64_t id = 0;
  std::string name;
  phase tick_phase = phase::cameras;
  wake_mode mode = wake_mode::every_tick;
  /// Answers `(report_atom, std::int64_t end_tick)` with a `link_report` when the run ends
  /// (links do).
  bool reports_at_end = false;
  /// Answers `(flush_atom)` with `done_atom` when the run ends, after handing its links what
  /// it still holds for them, before any participant reports (camera nodes do).
  bool flushes_at_end = false;
  /// The worker it runs on (HOST:PORT) in a distributed run; empty in the clock's own process.
  /// A participant lost with its connection ends the run naming it (docs/distributed.md).
  std::string host{};
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, participant_info& x) {
  return f(x.id, x.name, x.tick_phase, x.mode, x.reports_at_end, x.flushes_at_end, x.host);
}

}  // namespace argus::actors
