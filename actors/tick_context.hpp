#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "actors/phase.hpp"
#include "actors/tick_ack.hpp"
#include "events/event.hpp"

namespace argus::actors {

/// What a participant accumulates while it handles one tick: the events it emits, whom it
/// sent mail to and when it wants to run again. `finish()` turns that into the `tick_ack`.
class tick_context {
 public:
  /// Starts the bookkeeping of participant `id` (called `name` in the log) for `tick`.
  tick_context(std::uint64_t id, const std::string& name, std::int64_t tick, phase p)
      : name_(name), phase_(p) {
    ack_.participant = id;
    ack_.tick = tick;
  }

  /// The tick being handled.
  std::int64_t tick() const noexcept { return ack_.tick; }

  /// Appends an event; `fields_json` holds JSON members without braces (may be empty).
  void emit(std::string kind, std::string fields_json = {}) {
    sim_event ev;
    ev.tick = ack_.tick;
    ev.phase = static_cast<std::uint8_t>(phase_);
    ev.source_id = ack_.participant;
    ev.seq = seq_++;
    ev.source = name_;
    ev.kind = std::move(kind);
    ev.fields_json = std::move(fields_json);
    ack_.events.push_back(std::move(ev));
  }

  /// Appends one of the log's own events (events/event.hpp).
  void emit(const events::event& e) {
    emit(std::string(events::kind_of(e)), events::fields_json(e));
  }

  /// Records that mail went to participant `id`, so the clock ticks it to read it (its next
  /// turn).
  void sent_mail_to(std::uint64_t id) { ack_.woken.push_back(id); }

  /// Records that what this participant sent in this turn will reach participant `id` as one
  /// hand-over from a relay (a link actor, which the clock does not tick): the clock tells `id`
  /// with its next tick to wait for it (docs/network.md, "Announced hand-overs").
  void relayed_to(std::uint64_t id) { ack_.relayed.push_back(id); }

  /// Asks to be ticked again at `tick` (on-demand participants; the earliest request wins).
  void wake_at(std::int64_t tick) {
    if (ack_.next_wakeup == no_wakeup || tick < ack_.next_wakeup) ack_.next_wakeup = tick;
  }

  /// Ends the run after this tick, failing with `reason` (the first such reason wins).
  void stop_run(std::string reason) {
    if (ack_.stop_run.empty()) ack_.stop_run = std::move(reason);
  }

  /// The acknowledgement to send to the clock.
  tick_ack finish() && { return std::move(ack_); }

 private:
  const std::string& name_;
  phase phase_;
  std::uint32_t seq_ = 0;
  tick_ack ack_;
};

}  // namespace argus::actors
