#include "actors/link.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "actors/net_handover.hpp"
#include "actors/net_send_window.hpp"
#include "actors/participant_ids.hpp"
#include "actors/send_unattributed.hpp"
#include "actors/type_ids.hpp"
#include "config/derive_seed.hpp"
#include "fmt/format.h"
#include "protocol/link_model.hpp"

namespace argus::actors {
namespace {

struct endpoint {
  caf::actor handle;
  int node = 0;
  bool up = false;
};

// A message for an end that is down: kept until its due tick, in case the node comes back
// first (then it is handed over), else dropped.
struct waiting {
  std::int64_t due = 0;
  protocol::net_message message;
};

// Messages handed to a node ahead of their due tick: still ours to account for, until due,
// should a cut take them back or the node go down first. Counted by (due tick, kind, end), not
// listed one by one: what is on the wire is due within the longest delay, so a busy link holds
// a few dozen of these (a cache line or two per direction), whatever it carries.
struct handed_count {
  std::int64_t due = 0;
  std::uint32_t count = 0;
  std::uint16_t kind = 0;  // index into link_state::kinds
  std::uint8_t to = 0;
};

// The accounting of one message kind on this link.
struct kind_counts {
  protocol::message_kind kind;
  protocol::message_counts counts;
};

struct loss_burst {
  std::int64_t from = 0;
  std::int64_t until = 0;
  double loss = 0.0;
};

// Messages sent in [from, until) take `extra` ticks longer.
struct delay_spike {
  std::int64_t from = 0;
  std::int64_t until = 0;
  std::int64_t extra = 0;
};

// One direction of the link: messages sent by end `from` to the other end. Each has its own
// random stream and counters, so the two ends' mail can be read in either order (they flush
// in the same phase, and which reaches the link first is up to the threads) with the same
// outcome.
struct direction {
  pcg64 rng;
  std::int64_t last_due = 0;     // for FIFO delivery
  std::uint64_t handed_seq = 0;  // stamps what the receiver reads in canonical order
};

// What a read of the ends' mail touches first, in as few cache lines as it fits: at ten
// thousand nodes every read of a link starts with a miss per line (bench/RESULTS.md, "Link
// layer"). What only faults and the report need comes last.
struct link_state {
  std::array<endpoint, 2> ends;
  std::uint64_t id = 0;  // the link's participant id
  // Sent before this tick and the link was, or later got, cut: lost. Max while cut; the heal's
  // tick after. A batch can arrive after a cut or heal stamped later than it (an outbox hands
  // over once per lookahead), so a message is judged by when it was sent, not when read.
  std::int64_t cut_until = std::numeric_limits<std::int64_t>::min();
  std::uint16_t last_kind = 0;  // the kind looked up last (most traffic is of one kind at a time)
  bool reorder = false;
  std::array<direction, 2> directions;                // by sending end
  std::shared_ptr<const protocol::link_model> model;  // shared by every link of the network
  // In no order; those due before the tick the link last read mail in are pruned then.
  std::vector<handed_count> handed;
  // A link carries a handful of kinds: a short vector in order of first use.
  std::vector<kind_counts> kinds;
  // Loss bursts by start tick; a message sent at s takes the last one started by s.
  std::vector<loss_burst> bursts;
  std::vector<delay_spike> spikes;
  std::int64_t lookahead = 1;
  // Sent while the receiving end was down, by sending end.
  std::array<std::vector<waiting>, 2> for_down_end;
  participant_info info;

  // Table 2's loss probability, or a burst's for a message sent at `sent_tick`.
  double loss_at(std::int64_t sent_tick, double normal) const {
    for (auto it = bursts.rbegin(); it != bursts.rend(); ++it)
      if (it->from <= sent_tick) return sent_tick < it->until ? it->loss : normal;
    return normal;
  }

  // The delay added to a message sent at `sent_tick` (the longest spike it falls in).
  std::int64_t extra_delay_at(std::int64_t sent_tick) const {
    std::int64_t extra = 0;
    for (const auto& s : spikes)
      if (s.from <= sent_tick && sent_tick < s.until) extra = std::max(extra, s.extra);
    return extra;
  }

  // Index of `kind` in `kinds`, added on first use.
  std::uint16_t kind_index(protocol::message_kind kind) {
    if (last_kind < kinds.size() && kinds[last_kind].kind == kind) return last_kind;
    auto it = std::find_if(kinds.begin(), kinds.end(),
                           [&](const kind_counts& k) { return k.kind == kind; });
    if (it == kinds.end()) it = kinds.insert(kinds.end(), kind_counts{kind, {}});
    last_kind = static_cast<std::uint16_t>(it - kinds.begin());
    return last_kind;
  }

  protocol::message_counts& counter(protocol::message_kind kind) {
    return kinds[kind_index(kind)].counts;
  }

  protocol::accounting_by_kind accounting() const {
    protocol::accounting_by_kind out;
    for (const auto& k : kinds) out[k.kind.name()] += k.counts;
    return out;
  }
};

using link_actor = caf::stateful_actor<link_state>;

std::size_t end_of(const link_state& st, int node) {
  return st.ends[0].node == node ? 0 : 1;
}

// Hand-overs to end `to` (both ends when `to` is 2) due at `from_due` or later never reach
// their node: recount them from delivered to `lost` or `dropped`.
void recount_handed(link_state& st, std::size_t to, std::int64_t from_due, bool as_lost) {
  std::erase_if(st.handed, [&](const handed_count& h) {
    if (h.due < from_due || (to != 2 && h.to != to)) return false;
    auto& c = st.kinds[h.kind].counts;
    c.delivered -= h.count;
    (as_lost ? c.lost : c.dropped) += h.count;
    return true;
  });
}

// Messages for end `to`, which is down, due at or before `tick`: the node was down when they
// were due.
void drop_overdue(link_state& st, std::size_t to, std::int64_t tick) {
  std::erase_if(st.for_down_end[1 - to], [&](const waiting& w) {
    if (w.due > tick) return false;
    ++st.counter(w.message.kind).dropped;
    return true;
  });
}

// Counts a message of kind index `kind` as delivered to end `to`, due at `due`.
void count_delivered(link_state& st, std::size_t to, std::int64_t due, std::uint16_t kind) {
  ++st.kinds[kind].counts.delivered;
  auto it = std::find_if(st.handed.begin(), st.handed.end(), [&](const handed_count& h) {
    return h.due == due && h.kind == kind && h.to == to;
  });
  if (it != st.handed.end())
    ++it->count;
  else
    st.handed.push_back(handed_count{due, 1, kind, static_cast<std::uint8_t>(to)});
}

// Counts `message` (of kind index `kind`) as delivered to end `to`, due at `due`, and adds it
// to `out`.
void deliver(link_state& st, std::size_t to, std::int64_t due, std::uint16_t kind,
             protocol::net_message&& message, net_handover& out) {
  count_delivered(st, to, due, kind);
  ++message.hops;
  out.add(due, std::move(message));
}

// Sends end `to` what `out` holds as one hand-over, stamped `stamp` (the turn of the flush it
// answers, or of the command); an announced one goes even when empty, since the node counts.
void hand_over(link_actor* self, std::size_t to, mail_stamp stamp, bool announced,
               net_handover& out) {
  auto& st = self->state;
  if (out.empty() && !announced) return;
  auto& dir = st.directions[1 - to];
  stamp.sender = st.id;
  stamp.seq = dir.handed_seq;
  dir.handed_seq += out.size();
  send_unattributed(self, st.ends[to].handle,
                    net_deliver_mail{stamp, announced, st.ends[1 - to].node, std::move(out)});
}

// The fate of one message: lost, or due at `due` and, when duplicated, again at `again`.
struct verdict {
  bool lost = true;
  std::int64_t due = 0;
  std::optional<std::int64_t> again;
};

// Judges a message of kind index `kind` sent by end `from` at `sent_tick`, and counts it sent,
// lost or duplicated. One draw set per message whatever its fate.
verdict judge(link_state& st, std::size_t from, std::int64_t sent_tick, std::uint16_t kind) {
  auto& dir = st.directions[from];
  auto& c = st.kinds[kind].counts;
  ++c.sent;
  auto fate = st.model->draw(dir.rng, st.loss_at(sent_tick, st.model->loss()));
  verdict v;
  // A message read after a cut that came later than it was on the wire when the link was cut:
  // everything it could be due at is after the cut (due >= sent + lookahead > cut tick).
  if (fate.lost || sent_tick < st.cut_until) {
    ++c.lost;
    return v;
  }
  v.lost = false;
  v.due = sent_tick + fate.delay_ticks + st.extra_delay_at(sent_tick);
  if (!st.reorder) v.due = std::max(v.due, dir.last_due);
  dir.last_due = v.due;
  if (fate.duplicated) {
    ++c.duplicated;
    v.again = std::max(v.due, sent_tick + fate.duplicate_delay_ticks);
  }
  return v;
}

// What end `from` flushed in the turn `flushed`: every message's fate is decided now and what
// survives goes to the other end at once, each stamped with its due tick (the node reads it
// then). Nothing in it is due before the tick after the flush (it was sent at most a lookahead
// earlier), so the hand-over is in time; the clock knows of it when it was `announced`.
//
// The survivors stay where the window brought them (a hand-over takes over the window's
// storage): at ten thousand nodes a copy into fresh memory is a cache miss per message.
void carry(link_actor* self, int from_node, const mail_stamp& flushed, bool announced,
           net_send_window& window) {
  auto& st = self->state;
  auto from = end_of(st, from_node);
  auto to = 1 - from;
  bool up = st.ends[to].up;
  // Nothing due before this turn can be taken back by what comes later.
  std::erase_if(st.handed, [&](const handed_count& h) { return h.due < flushed.tick; });
  if (!up) drop_overdue(st, to, flushed.tick);
  auto& in = window.messages;
  net_handover out;
  if (up) out.due.reserve(in.size());
  net_handover again;  // second copies of duplicated messages, after the rest
  std::size_t kept = 0;
  auto place = [&](std::int64_t due, std::uint16_t kind, protocol::net_message&& m,
                   net_handover* elsewhere) {
    if (!up) {
      st.for_down_end[from].push_back(waiting{due, std::move(m)});
    } else if (elsewhere) {
      deliver(st, to, due, kind, std::move(m), *elsewhere);
    } else {
      count_delivered(st, to, due, kind);
      ++m.hops;
      if (&in[kept] != &m) in[kept] = std::move(m);
      out.due.push_back(due);
      ++kept;
    }
  };
  std::uint32_t i = 0;
  for (const auto& sent : window.ticks) {
    for (; i < sent.end; ++i) {
      auto kind = st.kind_index(in[i].kind);
      auto v = judge(st, from, sent.tick, kind);
      if (v.lost) continue;
      if (v.again) place(*v.again, kind, protocol::net_message(in[i]), &again);
      place(v.due, kind, std::move(in[i]), nullptr);
    }
  }
  if (!up) return;
  in.erase(in.begin() + static_cast<std::ptrdiff_t>(kept), in.end());
  out.messages = std::move(in);
  for (std::size_t k = 0; k < again.size(); ++k)
    out.add(again.due[k], std::move(again.messages[k]));
  hand_over(self, to, flushed, announced, out);
}

void apply(link_actor* self, const mail_stamp& stamp, const link_command& cmd) {
  auto& st = self->state;
  auto tick = stamp.tick;
  switch (cmd.op) {
    case link_op::attach: {
      auto end = end_of(st, cmd.node);
      auto& e = st.ends[end];
      e.handle = cmd.handle;
      e.up = static_cast<bool>(cmd.handle);
      if (!e.up) break;
      // Back before these were due: the fresh node gets them, in the order they were sent.
      drop_overdue(st, end, tick - 1);
      net_handover out;
      for (auto& w : st.for_down_end[1 - end]) {
        auto kind = st.kind_index(w.message.kind);
        deliver(st, end, w.due, kind, std::move(w.message), out);
      }
      st.for_down_end[1 - end].clear();
      hand_over(self, end, stamp, /*announced=*/false, out);
      break;
    }
    case link_op::node_down: {
      // The node's actor died with what it held: hand-overs due from now on were dropped.
      auto end = end_of(st, cmd.node);
      recount_handed(st, end, tick, /*as_lost=*/false);
      st.ends[end].handle = caf::actor{};
      st.ends[end].up = false;
      break;
    }
    case link_op::cut:
      // The cut catches everything on the wire: due from now on, handed over or held.
      st.cut_until = std::numeric_limits<std::int64_t>::max();
      for (const auto& e : st.ends)
        if (e.up) self->send(e.handle, net_retract_atom_v, st.id, tick);
      recount_handed(st, 2, tick, /*as_lost=*/true);
      for (auto& waiting : st.for_down_end) {
        for (auto& w : waiting) ++st.counter(w.message.kind).lost;
        waiting.clear();
      }
      break;
    case link_op::heal:
      if (st.cut_until > tick) st.cut_until = tick;
      break;
    case link_op::loss_burst:
      st.bursts.push_back(loss_burst{tick, cmd.until_tick, cmd.loss_probability});
      break;
    case link_op::delay_spike:
      st.spikes.push_back(delay_spike{tick, cmd.until_tick, cmd.extra_ticks});
      break;
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
  std::erase_if(st.spikes, [&](const delay_spike& s) { return s.until <= horizon; });
}

caf::behavior link(link_actor* self, participant_info info,
                   std::shared_ptr<const protocol::link_model> model, bool reorder,
                   std::int64_t lookahead, std::uint64_t seed, int a, int b) {
  auto& st = self->state;
  st.info = std::move(info);
  st.id = st.info.id;
  st.model = std::move(model);
  st.ends[0].node = a;
  st.ends[1].node = b;
  st.reorder = reorder;
  st.lookahead = lookahead;
  auto link_seed = config::derive_seed(seed, st.id);
  for (std::uint64_t d = 0; d < 2; ++d)
    st.directions[d].rng.seed(config::derive_seed(link_seed, d));
  return {
      [self](net_send_mail& mail) {
        carry(self, mail.from, mail.flushed, mail.announced, mail.window);
      },
      [self](link_cmd_atom, const mail_stamp& stamp, const link_command& cmd) {
        apply(self, stamp, cmd);
        forget_bursts(self->state, stamp.tick);
        return done_atom_v;
      },
      [self](report_atom, std::int64_t end_tick) {
        auto& st = self->state;
        auto counts = st.accounting();
        // Held for an end that is down: dropped if it was due within the run, else in flight.
        for (const auto& waiting : st.for_down_end)
          for (const auto& w : waiting)
            ++(w.due < end_tick ? counts[w.message.kind.name()].dropped
                                : counts[w.message.kind.name()].in_flight);
        // Handed over but due after the run: the node never read them.
        for (const auto& h : st.handed) {
          if (h.due < end_tick) continue;
          auto& c = counts[st.kinds[h.kind].kind.name()];
          c.delivered -= h.count;
          c.in_flight += h.count;
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
  info.mode = wake_mode::never;
  info.reports_at_end = true;
  return info;
}

std::shared_ptr<const protocol::link_model> make_link_model(const config::scenario& scenario) {
  return std::make_shared<const protocol::link_model>(scenario.network, scenario.run.tick.count());
}

caf::actor spawn_link(caf::actor_system& system, const config::scenario& scenario,
                      std::shared_ptr<const protocol::link_model> model, std::size_t index, int a,
                      int b) {
  auto lookahead =
      protocol::link_model::min_delay_ticks(scenario.network, scenario.run.tick.count());
  return system.spawn(link, link_participant(index, a, b), std::move(model),
                      scenario.network.reorder, lookahead, scenario.run.seed, a, b);
}

caf::actor spawn_link(caf::actor_system& system, const config::scenario& scenario,
                      std::size_t index, int a, int b) {
  return spawn_link(system, scenario, make_link_model(scenario), index, a, b);
}

}  // namespace argus::actors
