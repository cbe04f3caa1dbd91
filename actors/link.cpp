#include "actors/link.hpp"

#include <algorithm>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "actors/net_delivery.hpp"
#include "actors/net_send_batch.hpp"
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
  std::int64_t due = 0;
  std::uint64_t accepted = 0;  // acceptance order: ties of due tick go by it
  bool gone = false;           // handed over or dropped: erased after the pass
};

// Mail to a link: the messages one endpoint sent in one turn, or a command. One inbox for
// both, so that a cut, a heal or a burst takes effect between exactly the messages sent
// before and after it.
struct link_input {
  std::optional<link_command> command;
  int from = 0;
  std::vector<protocol::net_message> messages;
};

// A message handed to a node ahead of its due tick: still ours to account for, until it is
// due, should a cut take it back or the node go down first.
struct handed_over {
  std::int64_t due = 0;
  std::size_t to = 0;
  const std::string* kind = nullptr;  // key of `counts` in link_state::counts
  protocol::message_counts* counts = nullptr;
};

struct loss_burst {
  std::int64_t from = 0;
  std::int64_t until = 0;
  double loss = 0.0;
};

struct link_state {
  participant_info info;
  std::array<endpoint, 2> ends;
  std::unique_ptr<protocol::link_model> model;
  bool reorder = false;
  std::int64_t lookahead = 1;
  ordered_inbox<link_input> inbox;
  // Pending deliveries, in no order: a hand-over sorts what it takes by (due, accepted), a
  // deterministic order. One vector whose capacity stays: no allocation per message.
  std::vector<in_transit> pending;
  std::uint64_t accepted = 0;
  std::deque<handed_over> handed;              // in order of due tick
  std::array<std::int64_t, 2> last_due{0, 0};  // per direction, for FIFO delivery
  // Sent before this tick and the link was, or later got, cut: lost. Max while cut; the heal's
  // tick after. A batch can arrive after a cut or heal stamped later than it (an outbox hands
  // over once per lookahead), so a message is judged by when it was sent, not when read.
  std::int64_t cut_until = std::numeric_limits<std::int64_t>::min();
  // Loss bursts by start tick; a message sent at s takes the last one started by s.
  std::vector<loss_burst> bursts;
  std::uint64_t delivered_seq = 0;
  protocol::accounting_by_kind counts;
  // Most traffic is of one kind at a time: skip the string-keyed lookup when it repeats.
  const std::string* last_kind = nullptr;
  protocol::message_counts* last_counts = nullptr;

  // Table 2's loss probability, or a burst's for a message sent at `sent_tick`.
  double loss_at(std::int64_t sent_tick) const {
    for (auto it = bursts.rbegin(); it != bursts.rend(); ++it)
      if (it->from <= sent_tick) return sent_tick < it->until ? it->loss : model->loss();
    return model->loss();
  }

  protocol::message_counts& counter(const std::string& kind) {
    if (last_kind == nullptr || *last_kind != kind) {
      auto it = counts.try_emplace(kind).first;
      last_kind = &it->first;
      last_counts = &it->second;
    }
    return *last_counts;
  }
};

using link_actor = caf::stateful_actor<link_state>;

std::size_t end_of(const link_state& st, int node) {
  return st.ends[0].node == node ? 0 : 1;
}

// Hand-overs to end `to` (both ends when `to` is 2) due at `from_due` or later never reach
// their node: recount them from delivered to `lost` or `dropped`.
void recount_handed(link_state& st, std::size_t to, std::int64_t from_due, bool as_lost) {
  std::erase_if(st.handed, [&](const handed_over& h) {
    if (h.due < from_due || (to != 2 && h.to != to)) return false;
    --h.counts->delivered;
    ++(as_lost ? h.counts->lost : h.counts->dropped);
    return true;
  });
}

void apply(link_actor* self, std::int64_t tick, const link_command& cmd) {
  auto& st = self->state;
  switch (cmd.op) {
    case link_op::attach: {
      auto& e = st.ends[end_of(st, cmd.node)];
      e.handle = cmd.handle;
      e.up = static_cast<bool>(cmd.handle);
      break;
    }
    case link_op::node_down: {
      // The node's actor died with what it held: hand-overs due from now on were dropped.
      auto end = end_of(st, cmd.node);
      auto& e = st.ends[end];
      if (e.handle) self->send(e.handle, net_retract_atom_v, st.info.id, tick);
      recount_handed(st, end, tick, /*as_lost=*/false);
      e.handle = caf::actor{};
      e.up = false;
      break;
    }
    case link_op::cut:
      // The cut catches everything on the wire: due from now on, handed over or not.
      st.cut_until = std::numeric_limits<std::int64_t>::max();
      for (const auto& e : st.ends)
        if (e.up) self->send(e.handle, net_retract_atom_v, st.info.id, tick);
      recount_handed(st, 2, tick, /*as_lost=*/true);
      for (auto& t : st.pending) ++st.counter(t.message.kind).lost;
      st.pending.clear();
      break;
    case link_op::heal:
      if (st.cut_until > tick) st.cut_until = tick;
      break;
    case link_op::loss_burst:
      st.bursts.push_back(loss_burst{tick, cmd.until_tick, cmd.loss_probability});
      break;
  }
}

// `sent_tick` is when the endpoint sent it: the delay counts from then, and a cut or a loss
// burst applies by it. One draw set per message whatever its fate.
void accept(link_state& st, std::int64_t sent_tick, int from, protocol::net_message message) {
  in_transit t{from, std::move(message)};
  auto& c = st.counter(t.message.kind);
  ++c.sent;
  auto fate = st.model->draw(st.loss_at(sent_tick));
  // A message read after a cut that came later than it was on the wire when the link was cut:
  // everything it could be due at is after the cut (due >= sent + lookahead > cut tick).
  if (fate.lost || sent_tick < st.cut_until) {
    ++c.lost;
    return;
  }
  auto direction = end_of(st, t.from);
  auto due = sent_tick + fate.delay_ticks;
  if (!st.reorder) due = std::max(due, st.last_due[direction]);
  st.last_due[direction] = due;
  if (fate.duplicated) {
    ++c.duplicated;
    auto dup = t;
    dup.due = std::max(due, sent_tick + fate.duplicate_delay_ticks);
    dup.accepted = st.accepted++;
    st.pending.push_back(std::move(dup));
  }
  t.due = due;
  t.accepted = st.accepted++;
  st.pending.push_back(std::move(t));
}

// Hands over everything due before tick + lookahead: nothing sent from now on can be due that
// early, so the set is final. One CAF message per receiving end, whatever the number of
// network messages and due ticks in it; the node reads each at its due tick. A message for a
// node that is down stays until its due tick, in case the node comes back first; then it is
// dropped.
void hand_over(link_actor* self, tick_context& ctx) {
  auto& st = self->state;
  auto tick = ctx.tick();
  auto horizon = tick + st.lookahead;
  auto ready_end = std::partition(st.pending.begin(), st.pending.end(),
                                  [&](const in_transit& t) { return t.due < horizon; });
  std::sort(st.pending.begin(), ready_end, [](const in_transit& a, const in_transit& b) {
    return std::tie(a.due, a.accepted) < std::tie(b.due, b.accepted);
  });
  std::array<std::vector<net_delivery>, 2> out;
  for (auto it = st.pending.begin(); it != ready_end; ++it) {
    auto& t = *it;
    auto to = 1 - end_of(st, t.from);
    auto& c = st.counter(t.message.kind);
    if (!st.ends[to].up) {
      if (t.due <= tick) {
        ++c.dropped;
        t.gone = true;
      }
      continue;
    }
    ++c.delivered;
    if (t.due > tick) st.handed.push_back(handed_over{t.due, to, st.last_kind, &c});
    ++t.message.hops;
    if (out[to].empty()) out[to].reserve(static_cast<std::size_t>(ready_end - it));
    out[to].push_back(net_delivery{t.due, std::move(t.message)});
    t.gone = true;
  }
  std::erase_if(st.pending, [](const in_transit& t) { return t.gone; });
  for (std::size_t to = 0; to < 2; ++to) {
    if (out[to].empty()) continue;
    const auto& end = st.ends[to];
    auto first_due = out[to].front().due;
    mail_stamp stamp{tick, static_cast<std::uint8_t>(phase::network), st.info.id, st.delivered_seq};
    st.delivered_seq += out[to].size();
    self->send(end.handle, net_deliver_atom_v, stamp, st.ends[1 - to].node, std::move(out[to]));
    ctx.sent_mail_to(participant_ids::camera(end.node), first_due);
  }
}

// A burst matters to a message sent after it started and before the next one did. What an
// outbox still holds was sent at most a few lookaheads ago; bursts superseded before that go.
void forget_bursts(link_state& st, std::int64_t tick) {
  auto horizon = tick - 4 * st.lookahead;
  auto superseded = std::find_if(st.bursts.begin(), st.bursts.end(),
                                 [&](const loss_burst& b) { return b.from > horizon; });
  if (superseded != st.bursts.begin()) --superseded;  // the last one started by then stays
  st.bursts.erase(st.bursts.begin(), superseded);
}

caf::behavior link(link_actor* self, participant_info info, config::network_settings network,
                   double tick_seconds, std::uint64_t seed, int a, int b) {
  auto& st = self->state;
  st.info = std::move(info);
  st.ends[0].node = a;
  st.ends[1].node = b;
  st.reorder = network.reorder;
  st.lookahead = protocol::link_model::min_delay_ticks(network, tick_seconds);
  st.model = std::make_unique<protocol::link_model>(network, tick_seconds,
                                                    config::derive_seed(seed, st.info.id));
  return {
      [self](net_send_atom, int from, std::vector<net_send_batch>& batches) {
        for (auto& b : batches)
          self->state.inbox.put(b.stamp, link_input{std::nullopt, from, std::move(b.messages)});
      },
      [self](link_cmd_atom, const mail_stamp& stamp, link_command& cmd) {
        self->state.inbox.put(stamp, link_input{std::move(cmd), 0, {}});
      },
      [self](tick_atom, std::int64_t tick, std::uint8_t p) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        for (auto& [stamp, input] : st.inbox.take_due(tick, p)) {
          if (input.command) {
            apply(self, tick, *input.command);
            continue;
          }
          for (auto& m : input.messages) accept(st, stamp.tick, input.from, std::move(m));
        }
        while (!st.handed.empty() && st.handed.front().due <= tick) st.handed.pop_front();
        hand_over(self, ctx);
        // Nothing due before the horizon is left but for nodes that are down, so the next
        // hand-over is a lookahead later at the soonest; a node's own send wakes us as well.
        for (const auto& t : st.pending) ctx.wake_at(t.due);
        forget_bursts(st, tick);
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ctx).finish());
      },
      [self](report_atom, std::int64_t end_tick) {
        auto& st = self->state;
        auto counts = st.counts;
        // Sent in the last ticks, before the lookahead had us read them: on the wire still.
        for (const auto& [stamp, input] : st.inbox.take_due(end_tick + 1, 0))
          for (const auto& m : input.messages) {
            ++counts[m.kind].sent;
            ++counts[m.kind].in_flight;
          }
        for (const auto& t : st.pending) ++counts[t.message.kind].in_flight;
        // Handed over but due after the run: the node never read them.
        for (const auto& h : st.handed) {
          if (h.due < end_tick) continue;
          auto& c = counts[*h.kind];
          --c.delivered;
          ++c.in_flight;
        }
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
