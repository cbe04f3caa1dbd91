#pragma once

#include <cstdint>
#include <string>

#include "actors/participant_info.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"

namespace argus::actors {

/// How link number `index` between cameras `a` and `b` takes part in the clock: phase network,
/// on demand (an idle link costs nothing), reporting its accounting at the end.
participant_info link_participant(std::size_t index, int a, int b);

/// Spawns the actor of the link between cameras `a` and `b` (docs/network.md).
///
/// Mail it reads (each stamped, read in canonical order):
/// - `(net_send_atom, mail_stamp, int from_node, std::vector<net_message>)` from an endpoint,
///   everything it sends on this link in one turn: each message is lost (probability
///   `loss_probability`, or all of it while the link is cut), or delivered after a delay drawn
///   uniformly in [min_delay, max_delay] and rounded up to whole ticks; FIFO per direction unless
///   the scenario sets `reorder`; duplicated with `duplicate_probability`.
/// - `(link_cmd_atom, mail_stamp, link_command)`: attach a node's actor, node down, cut, heal,
///   loss burst.
/// It delivers what is due, hops + 1, as one `(net_deliver_atom, mail_stamp, int from_node,
/// std::vector<net_message>)` per receiving end per tick, or drops it when that node is down,
/// and answers `(report_atom)` with a `link_report`.
caf::actor spawn_link(caf::actor_system& system, const config::scenario& scenario,
                      std::size_t index, int a, int b);

}  // namespace argus::actors
