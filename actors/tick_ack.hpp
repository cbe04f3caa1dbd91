#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "actors/sim_event.hpp"

namespace argus::actors {

/// Sentinel for tick_ack::next_wakeup: no tick wanted until someone sends mail.
inline constexpr std::int64_t no_wakeup = -1;

/// A participant's answer to a tick: done with tick `tick`, wants to be ticked again at
/// `next_wakeup` (on-demand participants only), sent mail to the participants in `woken` (so
/// the clock ticks them to read it), sent mail through relays (links) that will hand each
/// participant in `relayed` one hand-over (so the clock tells it, with its next tick, how many
/// to wait for), and produced `events`.
///
/// Contract: a participant sends all its mail *before* its ack. Local CAF sends enqueue
/// synchronously, so once the clock holds every ack of a phase, every message of that phase
/// sits in its receiver's mailbox ahead of the receiver's next tick — except what goes through
/// a relay, which is why relayed mail is announced and counted (docs/network.md).
struct tick_ack {
  std::uint64_t participant = 0;
  std::int64_t tick = 0;
  std::int64_t next_wakeup = no_wakeup;
  std::vector<std::uint64_t> woken;
  std::vector<std::uint64_t> relayed;  // one entry per announced hand-over
  std::vector<sim_event> events;
  /// Set when the participant cannot go on (a strategy that raised): the run ends after this
  /// tick, its outputs complete up to it, and fails with this reason.
  std::string stop_run;

  friend bool operator==(const tick_ack&, const tick_ack&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, tick_ack& x) {
  return f(x.participant, x.tick, x.next_wakeup, x.woken, x.relayed, x.events, x.stop_run);
}

/// One participant's tick in a batch the clock sends a sub-clock (a distributed run's worker
/// host, which ticks the participants it hosts and answers with all their acks at once): who,
/// and the hand-overs announced to it (the `relayed` of a single tick).
struct batched_tick {
  std::uint64_t participant = 0;
  std::uint32_t relayed = 0;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, batched_tick& x) {
  return f(x.participant, x.relayed);
}

}  // namespace argus::actors
