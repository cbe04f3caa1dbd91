#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "actors/camera_node.hpp"
#include "actors/link_outbox.hpp"
#include "actors/net_arrivals.hpp"
#include "actors/ordered_inbox.hpp"
#include "actors/tick_context.hpp"
#include "controller/controller_io.hpp"
#include "protocol/node_network.hpp"

namespace argus::actors {

/// A message the operator or a test asks a camera node's network side to originate (the
/// strategy's own messages go straight to the network).
struct origination {
  int destination = protocol::broadcast;
  std::string kind;
  std::string body;
  bool expects_reply = false;
};

/// Reads what reached camera `camera` for (`tick`, `phase`), in canonical order, into `out`:
/// protocol messages for its strategy; bytes of a protocol kind that decode to nothing are
/// logged `bad_message` and dropped; anything else is the operator's or a test's, logged
/// `net_received` (a liveness probe is answered). Then what was asked to be originated goes
/// out, logged `net_sent`. Returns how many network messages arrived.
std::uint64_t read_mail(protocol::node_network& network, net_arrivals& arrivals,
                        ordered_inbox<origination>& to_originate, int camera, std::int64_t tick,
                        std::uint8_t phase, tick_context& ctx,
                        std::vector<controller::received_message>& out);

/// Puts what the network side sends this turn into `outbox`, one batch per link however many
/// messages it carries, and logs neighbour changes and failed requests. Returns how many
/// network messages went out.
std::uint64_t batch_outgoing(protocol::node_network& network, const link_directory& links,
                             link_outbox& outbox, int camera, tick_context& ctx);

}  // namespace argus::actors
