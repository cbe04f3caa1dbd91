#pragma once

#include <cstdint>
#include <map>

#include "actors/participant_info.hpp"
#include "caf/actor.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"

namespace argus::actors {

/// The link actor to one neighbour, as a camera node knows it: nothing about where the
/// neighbour is, only which link leads to it.
struct attached_link {
  std::uint64_t participant = 0;
  caf::actor handle;
};

/// A camera node's links, by the neighbour's camera id.
using link_directory = std::map<int, attached_link>;

/// How camera `camera` takes part in the clock: phase cameras, every tick (it senses each frame).
participant_info camera_participant(const config::camera_settings& camera);

/// Spawns the actor of one camera node; the caller joins it to the clock with
/// `camera_participant(camera)`, before the clock starts or from inside a tick, so that joins
/// stay deterministic.
///
/// Today the node announces itself (`node_up`) on its first tick and runs its network side
/// (`protocol::node_network`): hello beacons, neighbour discovery (`neighbour_up`,
/// `neighbour_lost` events), multi-hop forwarding, answers to `ping`, request time-outs
/// (`peer_failed`). Mail: `(net_deliver_mail)` and `(net_retract_atom, ...)` from its links
/// (docs/network.md); a tick waits for the hand-overs the clock announces with it;
/// `(net_originate_atom, mail_stamp, int destination, std::string kind, std::string body, bool
/// expects_reply)` asks it to send a message (`protocol::broadcast` for all within the hop
/// limit), read in its turn in canonical order and logged as `net_sent`. What it sends goes
/// through its outbox (actors/link_outbox.hpp): one `net_send_mail` per link per lookahead
/// window, and whatever is queued when it crashes (its exit handler) or when the run ends
/// (`(flush_atom)`, answered with `done_atom`). Sensing (vision/), the controller FSM of
/// Fig. 10 and the grouping protocol are not in it yet.
caf::actor spawn_camera_node(caf::actor_system& system, const config::scenario& scenario,
                             const config::camera_settings& camera, link_directory links);

}  // namespace argus::actors
