#pragma once

namespace argus::actors {

/// In which order a scheduler worker runs the actors it makes ready (docs/runtime.md,
/// "Scheduling order").
enum class scheduling_order {
  /// Each after the rest of the turn: fan-outs batch (actors/turn_order_scheduling.hpp).
  turn_order,
  /// CAF's own: each at once, while its mail is in cache. Kept to compare against.
  caf_default,
};

}  // namespace argus::actors
