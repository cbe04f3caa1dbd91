#pragma once

#include <cstdint>
#include <string>
#include <tuple>

namespace argus::actors {

/// One entry of the event log (`events.jsonl`). Participants hand their events to the clock
/// inside their tick acknowledgement; the clock orders each tick's events canonically
/// (phase, source id, seq), so the log is identical whatever thread produced them.
struct sim_event {
  std::int64_t tick = 0;
  std::uint8_t phase = 0;
  /// Stable id of the participant that produced the event (see participant_info::id).
  std::uint64_t source_id = 0;
  /// Per-source, per-tick sequence number: the order in which the source emitted them.
  std::uint32_t seq = 0;
  /// Readable source name, e.g. "camera/7".
  std::string source;
  /// Event kind, e.g. "node_up", "crash", "task_issued".
  std::string kind;
  /// The event's own fields as JSON members without braces, e.g. `"camera":7,"peer":2`.
  std::string fields_json;

  friend bool operator==(const sim_event&, const sim_event&) = default;
};

/// Canonical order of events within a tick.
inline bool canonical_less(const sim_event& a, const sim_event& b) noexcept {
  return std::tie(a.tick, a.phase, a.source_id, a.seq) <
         std::tie(b.tick, b.phase, b.source_id, b.seq);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, sim_event& x) {
  return f(x.tick, x.phase, x.source_id, x.seq, x.source, x.kind, x.fields_json);
}

}  // namespace argus::actors
