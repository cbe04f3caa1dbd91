#include "actors/camera_node.hpp"

#include <vector>

#include "actors/link_outbox.hpp"
#include "actors/net_arrivals.hpp"
#include "actors/participant_ids.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "fmt/format.h"
#include "protocol/link_model.hpp"
#include "protocol/node_network.hpp"

namespace argus::actors {
namespace {

// A message the node's controller (or, until the controller exists, the operator or a test)
// asks the network side to originate.
struct origination {
  int destination = protocol::broadcast;
  std::string kind;
  std::string body;
  bool expects_reply = false;
};

struct camera_node_state {
  participant_info info;
  int camera_id = 0;
  bool ptz = true;
  bool up_logged = false;  // `node_up` emitted
  link_directory links;
  std::unique_ptr<protocol::node_network> network;
  net_arrivals arrivals;
  ordered_inbox<origination> to_originate;
  // What this node sends on a link is never due before the links' lookahead: it goes to the
  // link once per lookahead window (docs/network.md, "Outbox").
  link_outbox outbox{1};
  // The last turn taken: what a flush outside a turn (crash, end of run) is stamped with.
  mail_stamp last_turn{-1, static_cast<std::uint8_t>(phase::cameras), 0, 0};
};

using node_actor = caf::stateful_actor<camera_node_state>;

// In a turn (`ctx` given) the hand-overs the links owe for it are announced to the clock;
// outside one (a crash, the end of the run) nobody waits for them.
void hand_to_links(node_actor* self, tick_context* ctx) {
  auto& st = self->state;
  st.outbox.flush(self, st.camera_id, st.last_turn, ctx != nullptr,
                  [&](std::uint64_t peer) { ctx->relayed_to(peer); });
}

std::vector<int> neighbours_of(const link_directory& links) {
  std::vector<int> out;
  for (const auto& [n, l] : links) out.push_back(n);
  return out;
}

void flush_network(node_actor* self, tick_context& ctx) {
  auto& st = self->state;
  // One batch per link per turn, however many network messages it carries.
  std::map<int, std::vector<protocol::net_message>> by_link;
  for (auto& out : st.network->take_outgoing())
    by_link[out.neighbour].push_back(std::move(out.message));
  for (auto& [neighbour, batch] : by_link) {
    auto it = st.links.find(neighbour);
    if (it == st.links.end()) continue;
    st.outbox.add(it->second.participant, it->second.handle, participant_ids::camera(neighbour),
                  ctx.tick(), std::move(batch));
  }
  if (st.outbox.window_ends(ctx.tick())) hand_to_links(self, &ctx);
  for (const auto& change : st.network->take_changes())
    ctx.emit(change.up ? "neighbour_up" : "neighbour_lost",
             fmt::format(R"("camera":{},"neighbour":{})", st.camera_id, change.neighbour));
  for (const auto& f : st.network->take_failures())
    ctx.emit("peer_failed",
             fmt::format(R"("camera":{},"peer":{},"request":"{}")", st.camera_id, f.peer, f.kind));
}

void take_turn(node_actor* self, std::int64_t tick, std::uint8_t p, const caf::actor& clock) {
  auto& st = self->state;
  st.last_turn = mail_stamp{tick, p, st.info.id, 0};
  tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
  if (!st.up_logged) {
    st.up_logged = true;
    ctx.emit("node_up",
             fmt::format(R"("camera":{},"type":"{}")", st.camera_id, st.ptz ? "ptz" : "static"));
  }
  st.arrivals.for_each_due(tick, p, [&](const mail_stamp&, int from, protocol::net_message& m) {
    st.network->receive(tick, from, m);
  });
  for (const auto& m : st.network->take_delivered()) {
    // A liveness probe any node may send; the controller's messages come with it.
    if (m.kind == "ping") st.network->reply(m, "pong", {});
    ctx.emit("net_received", fmt::format(R"("camera":{},"origin":{},"message":"{}","hops":{})",
                                         st.camera_id, m.origin, m.kind, m.hops));
  }
  for (auto& [stamp, o] : st.to_originate.take_due(tick, p)) {
    auto id = o.expects_reply ? st.network->request(tick, o.destination, o.kind, std::move(o.body))
                              : st.network->send(o.destination, o.kind, std::move(o.body));
    ctx.emit("net_sent", fmt::format(R"("camera":{},"destination":{},"message":"{}","id":{})",
                                     st.camera_id, o.destination, o.kind, id));
  }
  st.network->tick(tick);
  flush_network(self, ctx);
  self->send(clock, std::move(ctx).finish());
}

// A turn waits until every hand-over the clock announced for it has come (docs/network.md).
void take_turn_when_ready(node_actor* self) {
  if (auto t = self->state.arrivals.take_ready()) take_turn(self, t->tick, t->phase, t->clock);
}

caf::behavior camera_node(node_actor* self, const config::scenario& scenario,
                          config::camera_settings camera, link_directory links) {
  auto& st = self->state;
  st.info = camera_participant(camera);
  st.camera_id = camera.id;
  st.ptz = camera.type == config::camera_type::ptz;
  st.network = std::make_unique<protocol::node_network>(camera.id, neighbours_of(links), scenario);
  st.links = std::move(links);
  st.outbox = link_outbox{
      protocol::link_model::min_delay_ticks(scenario.network, scenario.run.tick.count())};
  // What the node sent before it went down was on the wire already: it still reaches the
  // links, and the fault injector waits for this node's end before the links run again.
  self->set_exit_handler([self](caf::exit_msg& msg) {
    hand_to_links(self, nullptr);
    self->quit(msg.reason);
  });
  return {
      // The run is over: the links count what is still queued as in flight.
      [self](flush_atom) {
        hand_to_links(self, nullptr);
        return done_atom_v;
      },
      [self](net_deliver_mail& mail) {
        self->state.arrivals.put(mail);
        take_turn_when_ready(self);
      },
      [self](net_retract_atom, std::uint64_t link, std::int64_t from_due) {
        self->state.arrivals.retract(link, from_due);
      },
      [self](net_originate_atom, const mail_stamp& stamp, int destination, std::string& kind,
             std::string& body, bool expects_reply) {
        self->state.to_originate.put(
            stamp, origination{destination, std::move(kind), std::move(body), expects_reply});
      },
      [self](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t relayed) {
        auto& st = self->state;
        st.arrivals.hold({tick, p, caf::actor_cast<caf::actor>(self->current_sender())}, relayed);
        take_turn_when_ready(self);
      },
  };
}

}  // namespace

participant_info camera_participant(const config::camera_settings& camera) {
  participant_info info{participant_ids::camera(camera.id), fmt::format("camera/{}", camera.id),
                        phase::cameras, wake_mode::every_tick};
  info.flushes_at_end = true;
  return info;
}

caf::actor spawn_camera_node(caf::actor_system& system, const config::scenario& scenario,
                             const config::camera_settings& camera, link_directory links) {
  return system.spawn(camera_node, scenario, camera, std::move(links));
}

}  // namespace argus::actors
