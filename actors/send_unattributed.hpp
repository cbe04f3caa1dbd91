#pragma once

#include <utility>

#include "caf/actor.hpp"
#include "caf/local_actor.hpp"
#include "caf/message_id.hpp"

namespace argus::actors {

/// Sends `xs...` to `dest` from `self` without naming `self` as the sender, on `self`'s worker.
///
/// A CAF message holds a reference to its sender, released when the receiver is done with it:
/// a write to the sender's control block from the receiver's thread, long after the sender ran.
/// In the link layer, where every turn moves mail through tens of thousands of actors, that
/// write is a cache miss per message (and a shared line between cores). Mail that names its
/// origin in its payload (a link's end, a node's id) does not need it. Unlike CAF's
/// `anon_send`, which hands a woken receiver to the scheduler's central queue, this keeps the
/// receiver on the sender's worker, as `send` does.
template <class... Ts>
void send_unattributed(caf::local_actor* self, const caf::actor& dest, Ts&&... xs) {
  if (dest)
    dest->eq_impl(caf::make_message_id(), nullptr, self->context(), std::forward<Ts>(xs)...);
}

}  // namespace argus::actors
