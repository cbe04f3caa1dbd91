#include "actors/node_mail.hpp"

#include <map>

#include "actors/participant_ids.hpp"
#include "fmt/format.h"
#include "protocol/group_messages.hpp"

namespace argus::actors {

std::uint64_t read_mail(protocol::node_network& network, net_arrivals& arrivals,
                        ordered_inbox<origination>& to_originate, int camera, std::int64_t tick,
                        std::uint8_t phase, tick_context& ctx,
                        std::vector<controller::received_message>& out) {
  std::uint64_t received = 0;
  arrivals.for_each_due(tick, phase, [&](const mail_stamp&, int from, protocol::net_message& m) {
    network.receive(tick, from, m);
    ++received;
  });
  for (auto& m : network.take_delivered()) {
    if (auto decoded = protocol::decode(m.kind.name(), m.body)) {
      out.push_back({m.origin, std::move(*decoded)});
      continue;
    }
    if (protocol::is_group_kind(m.kind.name())) {
      ctx.emit(events::bad_message{.camera = camera,
                                   .origin = m.origin,
                                   .message = std::string(m.kind.name()),
                                   .bytes = m.body.size()});
      continue;
    }
    if (m.kind == "ping") network.reply(m, "pong", {});
    ctx.emit(events::net_received{.camera = camera,
                                  .origin = m.origin,
                                  .message = std::string(m.kind.name()),
                                  .hops = m.hops});
  }
  for (auto& [stamp, o] : to_originate.take_due(tick, phase)) {
    auto id = o.expects_reply ? network.request(tick, o.destination, o.kind, std::move(o.body))
                              : network.send(o.destination, o.kind, std::move(o.body));
    ctx.emit(events::net_sent{
        .camera = camera, .destination = o.destination, .message = o.kind, .id = id});
  }
  return received;
}

std::uint64_t batch_outgoing(protocol::node_network& network, const link_directory& links,
                             link_outbox& outbox, int camera, tick_context& ctx) {
  std::map<int, std::vector<protocol::net_message>> by_link;
  std::uint64_t sent = 0;
  for (auto& out : network.take_outgoing()) {
    by_link[out.neighbour].push_back(std::move(out.message));
    ++sent;
  }
  for (auto& [neighbour, batch] : by_link) {
    auto it = links.find(neighbour);
    if (it == links.end()) continue;
    outbox.add(it->second.participant, it->second.handle, participant_ids::camera(neighbour),
               ctx.tick(), std::move(batch));
  }
  for (const auto& change : network.take_changes())
    ctx.emit(
        events::neighbour_change{.up = change.up, .camera = camera, .neighbour = change.neighbour});
  for (const auto& f : network.take_failures())
    ctx.emit(events::peer_failed{.camera = camera, .peer = f.peer, .request = f.kind});
  return sent;
}

}  // namespace argus::actors
