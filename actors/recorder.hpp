#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "actors/sim_event.hpp"
#include "caf/fwd.hpp"

namespace argus::actors {

/// What the recorder writes into `summary.json` besides the run's own figures.
struct recorder_settings {
  std::filesystem::path output_dir;
  std::string scenario;
  std::uint64_t seed = 0;
  double tick_seconds = 1.0 / 15.0;
  unsigned threads = 0;
  double speed = 0.0;
  /// Also hands each batch, once written, to this (the live console; display only). Empty for
  /// none.
  std::function<void(const std::vector<sim_event>&)> observer;
};

/// Spawns the recorder: it writes `output_dir/events.jsonl`, one JSON object per event,
///   {"t":<virtual seconds, 6 decimals>,"tick":N,"source":"camera/7","kind":"...",<fields>}
/// in the order it receives batches (the clock sends them in tick order, each batch already
/// canonically ordered), and on `(done_atom, run_result)` writes `summary.json`, answers with
/// the result completed by its event counts, and quits. Files are written under temporary
/// names and renamed when complete, so a crashed run leaves no half-written output behind.
///
/// Messages: `(record_atom, int64 tick, std::vector<sim_event>)` -> sends
/// `(recorded_atom, int64 tick)` back; `(done_atom, run_result)` -> `run_result`.
caf::actor spawn_recorder(caf::actor_system& system, recorder_settings settings);

}  // namespace argus::actors
