#pragma once

// A participant that exchanges randomised mail with its peers, for the determinism tests and
// the runtime benchmarks: whatever thread runs which actor when, the events it emits must be
// the same for the same seed.

#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <vector>

#include "actors/ordered_inbox.hpp"
#include "actors/participant_info.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "config/derive_seed.hpp"
#include "fmt/format.h"

using chat_atom = caf::atom_constant<caf::atom("chat")>;

namespace argus::actors::testing {

/// Where a chatter's peers are; filled in before the run starts, read-only afterwards.
using peer_directory = std::map<std::uint64_t, caf::actor>;

struct chatter_state {
  participant_info info;
  std::mt19937_64 rng;
  ordered_inbox<std::int64_t> inbox;
  std::uint64_t sent = 0;
  std::uint64_t digest = 1469598103934665603ULL;
};

/// Each tick: reads its due mail in canonical order and folds it into a digest (emitted as a
/// `chat` event), then sends 0-3 messages with random values to random peers.
inline caf::behavior chatter(caf::stateful_actor<chatter_state>* self, participant_info info,
                             std::uint64_t seed, std::shared_ptr<const peer_directory> peers) {
  self->state.info = info;
  self->state.rng.seed(config::derive_seed(seed, info.id));
  return {
      [self](chat_atom, std::int64_t tick, std::uint8_t p, std::uint64_t sender, std::uint64_t seq,
             std::int64_t value) {
        self->state.inbox.put(mail_stamp{tick, p, sender, seq}, value);
      },
      [self, peers](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        auto due = st.inbox.take_due(tick, p);
        for (const auto& [stamp, value] : due)
          st.digest =
              (st.digest ^ static_cast<std::uint64_t>(value) ^ stamp.sender) * 1099511628211ULL;
        ctx.emit("chat", fmt::format(R"("read":{},"digest":{})", due.size(), st.digest));
        std::uniform_int_distribution<int> how_many(0, 3);
        std::uniform_int_distribution<std::size_t> pick(0, peers->size() - 1);
        std::uniform_int_distribution<std::int64_t> value(-1000000, 1000000);
        for (int n = how_many(st.rng); n > 0; --n) {
          auto it = std::next(peers->begin(), static_cast<std::ptrdiff_t>(pick(st.rng)));
          self->send(it->second, chat_atom::value, tick, p, st.info.id, st.sent++, value(st.rng));
          ctx.sent_mail_to(it->first);
        }
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ctx).finish());
      },
  };
}

}  // namespace argus::actors::testing
