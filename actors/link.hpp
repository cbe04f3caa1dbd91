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
/// - `(net_send_atom, int from_node, std::vector<net_send_batch>)` from an endpoint's outbox
///   (actors/link_outbox.hpp), what it sent on this link in each turn of a window, each batch
///   with that turn's stamp. Each message is lost (probability `loss_probability`, a loss
///   burst's if sent during one, always if sent while the link was cut or on the wire when it
///   was cut, judged by send tick however late it is read), or delivered after a delay drawn
///   uniformly in [min_delay, max_delay] and rounded up to whole ticks; FIFO per direction unless
///   the scenario sets `reorder`; duplicated with `duplicate_probability`.
/// - `(link_cmd_atom, mail_stamp, link_command)`: attach a node's actor, node down, cut, heal,
///   loss burst.
/// Woken at tick t, it hands over everything due before t + lookahead (the minimum delay in
/// ticks: nothing sent from t on can be due sooner) as one `(net_deliver_atom, mail_stamp,
/// int from_node, std::vector<net_delivery>)` per receiving end, hops + 1, each message to be
/// read at its due tick; a cut sends `(net_retract_atom, std::uint64_t link_id, std::int64_t
/// from_due)` for what it caught. It answers `(report_atom, std::int64_t end_tick)` with a
/// `link_report`. docs/network.md, "Lookahead", explains why this changes no outcome.
caf::actor spawn_link(caf::actor_system& system, const config::scenario& scenario,
                      std::size_t index, int a, int b);

}  // namespace argus::actors
