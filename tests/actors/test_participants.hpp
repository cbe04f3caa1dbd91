#pragma once

// Participants and a recorder stand-in for the actor-layer tests.

#include <memory>
#include <string>
#include <vector>

#include "actors/participant_info.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"

namespace argus::actors::testing {

/// What a probe participant saw, shared with the test body.
struct probe_log {
  std::vector<std::string> ticks;  // "tick:phase:name"
};

/// A participant that records every tick it gets into `log`, emits one `probe` event, wakes
/// the participants in `wakes` at every tick and asks to be woken again after `period` ticks
/// (0 = never; on-demand participants only).
inline caf::behavior probe(caf::event_based_actor* self, participant_info info,
                           std::shared_ptr<probe_log> log, std::vector<std::uint64_t> wakes,
                           std::int64_t period) {
  return {
      [=](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t) {
        log->ticks.push_back(std::to_string(tick) + ":" + std::to_string(p) + ":" + info.name);
        tick_context ctx(info.id, info.name, tick, info.tick_phase);
        ctx.emit("probe");
        for (auto id : wakes) ctx.sent_mail_to(id);
        if (period > 0) ctx.wake_at(tick + period);
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ctx).finish());
      },
  };
}

/// A participant that never answers on its own; the test injects or withholds its acks.
/// (`name` is only for debugging; it also keeps CAF 0.17's spawn from dereferencing an empty
/// argument tuple, which UBSan reports.)
inline caf::behavior silent(caf::event_based_actor*, std::string /*name*/) {
  return {
      [](tick_atom, std::int64_t, std::uint8_t, std::uint32_t) {
        // nop: the test decides whether this participant answers
      },
  };
}

/// What the recorder stand-in received.
struct recorded {
  std::vector<sim_event> events;
  bool done = false;
};

/// Stands in for the recorder: keeps the batches in memory and acknowledges them.
inline caf::behavior fake_recorder(caf::event_based_actor* self, std::shared_ptr<recorded> out) {
  return {
      [=](record_atom, std::int64_t tick, const std::vector<sim_event>& batch) {
        out->events.insert(out->events.end(), batch.begin(), batch.end());
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), recorded_atom_v, tick);
      },
      [=](done_atom, run_result& r) {
        out->done = true;
        r.events_total = out->events.size();
        self->quit();
        return r;
      },
  };
}

}  // namespace argus::actors::testing
