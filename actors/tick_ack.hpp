#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "actors/sim_event.hpp"
#include "actors/wire_block.hpp"
#include "caf/deserializer.hpp"
#include "caf/error.hpp"
#include "caf/sec.hpp"
#include "caf/serializer.hpp"

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
  std::uint32_t unused = 0;  // no padding: a batch crosses as its bytes
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, batched_tick& x) {
  return f(x.participant, x.relayed);
}

// A sub-clock's batches and answers cross once a phase per worker, with a record for each of its
// cameras (512 of the large station's 1,024 on each of two workers): CAF would write and read
// them field by field, through a virtual call each, on every tick's critical path. They cross
// as blocks of bytes instead (wire_block.hpp). Found by argument-dependent lookup, these take
// the place of CAF's own sequence for the two vectors wherever the types are known.

/// A batch: its records' bytes.
template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, std::vector<batched_tick>& x) {
  if constexpr (std::is_base_of_v<caf::serializer, Inspector> ||
                std::is_base_of_v<caf::deserializer, Inspector>) {
    return f(as_block(x));
  } else {
    auto count = x.size();  // not a wire: printing, say
    return f(count);
  }
}

/// What an answer's acknowledgement has whatever it carries, as it crosses; how many of the
/// woken, relayed, events and stop_run characters that follow the block are its.
struct ack_head {
  std::uint64_t participant = 0;
  std::int64_t tick = 0;
  std::int64_t next_wakeup = 0;
  std::uint32_t woken = 0;
  std::uint32_t relayed = 0;
  std::uint32_t events = 0;
  std::uint32_t stop_run_chars = 0;
};

/// An answer: the acknowledgements' heads in one block, then everything they carry, in order.
template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, std::vector<tick_ack>& x) {
  if constexpr (std::is_base_of_v<caf::serializer, Inspector>) {
    std::vector<ack_head> heads;
    std::vector<std::uint64_t> woken;
    std::vector<std::uint64_t> relayed;
    std::vector<sim_event> events;
    std::string stops;
    heads.reserve(x.size());
    for (const auto& a : x) {
      heads.push_back({a.participant, a.tick, a.next_wakeup,
                       static_cast<std::uint32_t>(a.woken.size()),
                       static_cast<std::uint32_t>(a.relayed.size()),
                       static_cast<std::uint32_t>(a.events.size()),
                       static_cast<std::uint32_t>(a.stop_run.size())});
      woken.insert(woken.end(), a.woken.begin(), a.woken.end());
      relayed.insert(relayed.end(), a.relayed.begin(), a.relayed.end());
      events.insert(events.end(), a.events.begin(), a.events.end());
      stops += a.stop_run;
    }
    return f(as_block(heads), as_block(woken), as_block(relayed), events, stops);
  } else if constexpr (std::is_base_of_v<caf::deserializer, Inspector>) {
    std::vector<ack_head> heads;
    std::vector<std::uint64_t> woken;
    std::vector<std::uint64_t> relayed;
    std::vector<sim_event> events;
    std::string stops;
    if (auto err = f(as_block(heads), as_block(woken), as_block(relayed), events, stops))
      return err;
    x.clear();
    x.reserve(heads.size());
    runs_of woken_runs(woken);
    runs_of relayed_runs(relayed);
    runs_of event_runs(events);
    runs_of stop_runs(stops);
    for (const auto& h : heads) {
      tick_ack a;
      a.participant = h.participant;
      a.tick = h.tick;
      a.next_wakeup = h.next_wakeup;
      if (!woken_runs.take(h.woken, a.woken) || !relayed_runs.take(h.relayed, a.relayed) ||
          !event_runs.take(h.events, a.events) || !stop_runs.take(h.stop_run_chars, a.stop_run))
        return caf::make_error(caf::sec::invalid_argument);
      x.push_back(std::move(a));
    }
    if (!woken_runs.all_taken() || !relayed_runs.all_taken() || !event_runs.all_taken() ||
        !stop_runs.all_taken())
      return caf::make_error(caf::sec::invalid_argument);
    return caf::error{};
  } else {
    auto count = x.size();  // not a wire: printing, say
    return f(count);
  }
}

}  // namespace argus::actors
