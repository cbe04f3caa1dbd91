#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "protocol/message_accounting.hpp"

namespace argus::actors {

/// What a finished run reports (the clock fills the timing, the recorder the event counts);
/// written to `summary.json`.
struct run_result {
  std::int64_t ticks = 0;
  double virtual_seconds = 0.0;
  double wall_seconds = 0.0;
  std::uint64_t participants = 0;
  /// Participants that died without being retired by a fault (names, in order noticed).
  std::vector<std::string> unexpected_down;
  /// Workers lost during a run that went on without them (`--on-worker-loss crash-nodes`),
  /// each as "HOST:PORT at tick T".
  std::vector<std::string> lost_workers;
  std::uint64_t events_total = 0;
  std::map<std::string, std::uint64_t> events_by_kind;
  /// Message fates per link ("link/1-2") and kind, from the links' end-of-run reports.
  std::map<std::string, protocol::accounting_by_kind> links;
  /// Why the run ended before its end tick (a participant asked to stop: a strategy that
  /// raised); empty when it ran to its end.
  std::string failure;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, run_result& x) {
  return f(x.ticks, x.virtual_seconds, x.wall_seconds, x.participants, x.unexpected_down,
           x.lost_workers, x.events_total, x.events_by_kind, x.links, x.failure);
}

}  // namespace argus::actors
