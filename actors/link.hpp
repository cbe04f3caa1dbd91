#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "actors/participant_info.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"
#include "protocol/link_model.hpp"

namespace argus::actors {

/// How link number `index` between cameras `a` and `b` takes part in the clock: never ticked
/// (it works on its mail alone), reporting its accounting at the end.
participant_info link_participant(std::size_t index, int a, int b);

/// Spawns the actor of the link between cameras `a` and `b` (docs/network.md).
///
/// Mail it reads, each as it comes (the barrier orders what matters: commands come in the
/// faults phase, the ends' mail in the cameras phase, and the two directions share nothing
/// that depends on which end's mail is read first):
/// - `(net_send_mail)` (from_node, mail_stamp flushed, bool announced, net_send_window) from
///   an endpoint's outbox (actors/link_outbox.hpp), what it sent on this link in each turn of
///   a window, each tick's share with that tick. Each
///   message is lost (probability `loss_probability`, a loss burst's if sent during one,
///   always if sent while the link was cut or on the wire when it was cut, judged by send
///   tick), or delivered after a delay drawn uniformly in [min_delay, max_delay] and rounded
///   to whole ticks; FIFO per direction unless the scenario sets `reorder`; duplicated with
///   `duplicate_probability`. What survives goes to the other end at once as one
///   `(net_deliver_mail)` (mail_stamp, bool announced, int from_node, net_handover)
///   (hops + 1, each message to be read at its due tick), sent even when empty if `announced`:
///   the receiver waits for it. For an end that is down, messages wait for its return until
///   they are due, then are dropped.
/// - `(link_cmd_atom, mail_stamp, link_command)` -> `done_atom`: attach a node's actor (and
///   hand it what waited for it), node down, cut (a `(net_retract_atom, std::uint64_t link_id,
///   std::int64_t from_due)` to each end for what it caught), heal, loss burst. The answer
///   comes once its effects are sent: the fault injector waits for it.
/// - `(report_atom, std::int64_t end_tick)` -> `link_report`.
///
/// Its messages' fates are drawn from `model`, which every link of a network shares (one copy
/// of the parameters stays in cache while tens of thousands of links read it), each direction
/// from a random stream of its own seeded from the run seed and the link's id.
caf::actor spawn_link(caf::actor_system& system, const config::scenario& scenario,
                      std::shared_ptr<const protocol::link_model> model, std::size_t index, int a,
                      int b);

/// The scenario's link model, to share among the links `spawn_link` makes.
std::shared_ptr<const protocol::link_model> make_link_model(const config::scenario& scenario);

/// Spawns a link with a model of its own (tests, a single link).
caf::actor spawn_link(caf::actor_system& system, const config::scenario& scenario,
                      std::size_t index, int a, int b);

}  // namespace argus::actors
