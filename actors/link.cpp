#include "actors/link.hpp"

#include <map>
#include <tuple>

#include "actors/ordered_inbox.hpp"
#include "actors/participant_ids.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "config/derive_seed.hpp"
#include "fmt/format.h"
#include "protocol/link_model.hpp"

namespace argus::actors {
namespace {

struct endpoint {
  int node = 0;
  caf::actor handle;
  bool up = false;
};

struct in_transit {
  int from = 0;
  protocol::net_message message;
};

struct link_state {
  participant_info info;
  std::array<endpoint, 2> ends;
  std::unique_ptr<protocol::link_model> model;
  bool reorder = false;
  ordered_inbox<in_transit> outgoing;
  ordered_inbox<link_command> commands;
  // Pending deliveries by (due tick, order of acceptance): a deterministic order.
  std::map<std::pair<std::int64_t, std::uint64_t>, in_transit> pending;
  std::uint64_t accepted = 0;
  std::array<std::int64_t, 2> last_due{0, 0};  // per direction, for FIFO delivery
  bool cut = false;
  double burst_loss = 0.0;
  std::int64_t burst_until = -1;
  std::uint64_t delivered_seq = 0;
  protocol::accounting_by_kind counts;
};

std::size_t end_of(const link_state& st, int node) {
  return st.ends[0].node == node ? 0 : 1;
}

void apply(link_state& st, const link_command& cmd) {
  switch (cmd.op) {
    case link_op::attach: {
      auto& e = st.ends[end_of(st, cmd.node)];
      e.handle = cmd.handle;
      e.up = static_cast<bool>(cmd.handle);
      break;
    }
    case link_op::node_down: {
      auto& e = st.ends[end_of(st, cmd.node)];
      e.handle = caf::actor{};
      e.up = false;
      break;
    }
    case link_op::cut:
      st.cut = true;
      break;
    case link_op::heal:
      st.cut = false;
      break;
    case link_op::loss_burst:
      st.burst_loss = cmd.loss_probability;
      st.burst_until = cmd.until_tick;
      break;
  }
}

// `sent_tick` is when the endpoint sent it: the delay counts from then.
void accept(link_state& st, std::int64_t sent_tick, in_transit t) {
  auto& c = st.counts[t.message.kind];
  ++c.sent;
  if (st.cut) {
    ++c.lost;
    return;
  }
  double loss = sent_tick < st.burst_until ? st.burst_loss : -1.0;
  auto fate = loss >= 0.0 ? st.model->draw(loss) : st.model->draw();
  if (fate.lost) {
    ++c.lost;
    return;
  }
  auto direction = end_of(st, t.from);
  auto due = sent_tick + fate.delay_ticks;
  if (!st.reorder) due = std::max(due, st.last_due[direction]);
  st.last_due[direction] = due;
  if (fate.duplicated) {
    ++c.duplicated;
    auto dup_due = std::max(due, sent_tick + fate.duplicate_delay_ticks);
    st.pending.emplace(std::make_pair(dup_due, st.accepted++), t);
  }
  st.pending.emplace(std::make_pair(due, st.accepted++), std::move(t));
}

void deliver_due(caf::stateful_actor<link_state>* self, tick_context& ctx) {
  auto& st = self->state;
  while (!st.pending.empty() && st.pending.begin()->first.first <= ctx.tick()) {
    auto t = std::move(st.pending.begin()->second);
    st.pending.erase(st.pending.begin());
    auto& c = st.counts[t.message.kind];
    if (st.cut) {
      ++c.lost;  // the cut caught it on the wire
      continue;
    }
    auto& to = st.ends[1 - end_of(st, t.from)];
    if (!to.up) {
      ++c.dropped;
      continue;
    }
    ++c.delivered;
    ++t.message.hops;
    mail_stamp stamp{ctx.tick(), static_cast<std::uint8_t>(phase::network), st.info.id,
                     st.delivered_seq++};
    self->send(to.handle, net_deliver_atom_v, stamp, t.from, std::move(t.message));
    ctx.sent_mail_to(participant_ids::camera(to.node));
  }
}

caf::behavior link(caf::stateful_actor<link_state>* self, participant_info info,
                   config::network_settings network, double tick_seconds, std::uint64_t seed, int a,
                   int b) {
  auto& st = self->state;
  st.info = std::move(info);
  st.ends[0].node = a;
  st.ends[1].node = b;
  st.reorder = network.reorder;
  st.model = std::make_unique<protocol::link_model>(network, tick_seconds,
                                                    config::derive_seed(seed, st.info.id));
  return {
      [self](net_send_atom, const mail_stamp& stamp, int from, protocol::net_message& m) {
        self->state.outgoing.put(stamp, in_transit{from, std::move(m)});
      },
      [self](link_cmd_atom, const mail_stamp& stamp, link_command& cmd) {
        self->state.commands.put(stamp, std::move(cmd));
      },
      [self](tick_atom, std::int64_t tick, std::uint8_t p) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        for (auto& [stamp, cmd] : st.commands.take_due(tick, p)) apply(st, cmd);
        for (auto& [stamp, t] : st.outgoing.take_due(tick, p)) accept(st, stamp.tick, std::move(t));
        deliver_due(self, ctx);
        if (!st.pending.empty()) ctx.wake_at(st.pending.begin()->first.first);
        if (st.burst_until > tick) ctx.wake_at(st.burst_until);
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ctx).finish());
      },
      [self](report_atom) {
        auto& st = self->state;
        auto counts = st.counts;
        for (const auto& [key, t] : st.pending) ++counts[t.message.kind].in_flight;
        return link_report{st.info.name, std::move(counts)};
      },
  };
}

}  // namespace

participant_info link_participant(std::size_t index, int a, int b) {
  participant_info info;
  info.id = participant_ids::link(index);
  info.name = fmt::format("link/{}-{}", a, b);
  info.tick_phase = phase::network;
  info.mode = wake_mode::on_demand;
  info.reports_at_end = true;
  return info;
}

caf::actor spawn_link(caf::actor_system& system, const config::scenario& scenario,
                      std::size_t index, int a, int b) {
  return system.spawn(link, link_participant(index, a, b), scenario.network,
                      scenario.run.tick.count(), scenario.run.seed, a, b);
}

}  // namespace argus::actors
