// Messages per second through the link layer (issues 6 and 17): N nodes in a random geometric
// graph with mean degree about 8; links draw Table 2 delay and loss and deliver; every node
// reads what arrives each turn, as a camera node does. Two kinds of node:
//
// - `links` (mode 0): every node sends K messages per tick on each of its links (K = 1: the
//   worst case for batching; K = 2, 4, 8: bursts such as a query to every neighbour plus
//   forwarding) through an outbox, as camera nodes do. 1 and 2 scheduler threads; with 2, the
//   clock on a worker and on its own thread. At burst 1, under CAF's scheduling order as well as
//   Argus's turn order (actors/turn_order_scheduling.hpp).
// - `node_network` (mode 1): every node runs a protocol::node_network, as a camera node does:
//   hello beacons every second, and one broadcast a second of its own (staggered by node id),
//   flooded within the hop limit with duplicate suppression. K is unused.
//
// Counted (per run; the counters are means over the iterations):
//   delivered_per_s   messages the links delivered to a node (due within the run), over the
//                     clock's wall time, first tick and end of run included;
//   steady_per_s      messages nodes read in their turns between two measured instants (the
//                     first node's turn in the first steady tick and in the last tick), over the
//                     time between them: no formula, what arrived and when;
//   accepted, lost, dropped, in_flight
//                     what the links accepted and what became of what was not delivered;
//   app_per_s         (node_network) messages handed to the nodes' controllers: each broadcast
//                     once per node it reached, copies suppressed.
//
//   build/bench/link_bench --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>

#include "actors/clock.hpp"
#include "actors/link.hpp"
#include "actors/link_command.hpp"
#include "actors/link_outbox.hpp"
#include "actors/net_arrivals.hpp"
#include "actors/participant_ids.hpp"
#include "actors/recorder.hpp"
#include "actors/system_config.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "config/ticks.hpp"
#include "protocol/link_model.hpp"
#include "protocol/node_network.hpp"
#include "protocol/topology.hpp"

namespace {

using namespace argus;
using namespace argus::actors;

// When the first node took its turn in two ticks: the steady part of a run lies between them,
// past the first ticks (every link joins, the first windows go out, neighbours are found) and
// before the end (every node flushes, every link reports).
struct steady_marks {
  std::int64_t from_tick = 0;
  std::int64_t to_tick = 0;
  std::atomic<std::int64_t> from_ns{0};
  std::atomic<std::int64_t> to_ns{0};

  bool steady(std::int64_t tick) const noexcept { return tick >= from_tick && tick < to_tick; }

  void mark(std::int64_t tick) {
    auto at = [&]() -> std::atomic<std::int64_t>* {
      if (tick == from_tick) return &from_ns;
      if (tick == to_tick) return &to_ns;
      return nullptr;
    }();
    if (at == nullptr || at->load(std::memory_order_relaxed) != 0) return;
    std::int64_t none = 0;
    auto now = std::chrono::steady_clock::now().time_since_epoch();
    at->compare_exchange_strong(none, std::chrono::nanoseconds(now).count());
  }

  double seconds() const { return static_cast<double>(to_ns.load() - from_ns.load()) * 1e-9; }
};

// A node's links, and what it read: written by the node's actor only, read once the run is over.
struct node_links {
  struct entry {
    caf::actor handle;
    std::uint64_t id;    // the link's participant id
    std::uint64_t peer;  // the other end's participant id
    int neighbour;       // the other end's node
  };
  std::vector<entry> links;
  std::uint64_t read_steady = 0;  // messages read in turns of the steady ticks
  std::uint64_t app_total = 0;    // messages handed to the controller (node_network)
  std::uint64_t app_steady = 0;

  const entry* to(int neighbour) const {
    for (const auto& l : links)
      if (l.neighbour == neighbour) return &l;
    return nullptr;
  }
};

struct node_state {
  link_outbox outbox{1};
  net_arrivals arrivals;
  std::unique_ptr<protocol::node_network> network;  // node_network mode only
  std::uint32_t seq = 0;
};

using node_actor = caf::stateful_actor<node_state>;

// Interned once, as a node's protocol would: a kind made from its name takes a lock.
const protocol::message_kind bench_kind{"bench"};

// Reads what is due, then calls `send(ctx)` and hands the outbox to the links at the end of a
// window, as a camera node's turn does.
template <class OnMessage, class Send>
void take_turn(node_actor* self, int node, const net_arrivals::turn& t, node_links& mine,
               steady_marks& marks, OnMessage on_message, Send send) {
  auto& st = self->state;
  marks.mark(t.tick);
  tick_context ctx(participant_ids::camera(node), "n", t.tick, phase::cameras);
  std::uint64_t read = 0;
  st.arrivals.for_each_due(t.tick, t.phase,
                           [&](const mail_stamp&, int from, protocol::net_message& m) {
                             ++read;
                             on_message(from, m);
                           });
  if (marks.steady(t.tick)) mine.read_steady += read;
  send(t.tick);
  mail_stamp now{t.tick, t.phase, participant_ids::camera(node), 0};
  if (st.outbox.window_ends(t.tick))
    st.outbox.flush(self, node, now, true, [&](std::uint64_t peer) { ctx.relayed_to(peer); });
  self->send(t.clock, std::move(ctx).finish());
}

// `links` mode: `burst` messages per link per turn; each message read as a camera reads it, its
// header, to decide what it is.
void blast(node_actor* self, int node, int burst, node_links& mine, const net_arrivals::turn& t,
           steady_marks& marks) {
  auto& st = self->state;
  std::uint64_t valid = 0;
  take_turn(
      self, node, t, mine, marks,
      [&](int, const protocol::net_message& m) { valid += m.id != 0 && !m.kind.empty(); },
      [&](std::int64_t tick) {
        for (const auto& l : mine.links)
          for (int i = 0; i < burst; ++i) {
            protocol::net_message m;
            m.id = protocol::make_message_id(node, st.seq++);
            m.origin = node;
            m.kind = bench_kind;
            st.outbox.add(l.id, l.handle, l.peer, tick, std::move(m));
          }
      });
  benchmark::DoNotOptimize(valid);
}

// `node_network` mode: arrivals go through the node's network (beacons, flooding, duplicate
// suppression); once a second (staggered by node id) the node floods a message of its own.
void flood(node_actor* self, int node, std::int64_t period, node_links& mine,
           const net_arrivals::turn& t, steady_marks& marks) {
  auto& net = *self->state.network;
  take_turn(
      self, node, t, mine, marks,
      [&](int from, const protocol::net_message& m) { net.receive(t.tick, from, m); },
      [&](std::int64_t tick) {
        net.tick(tick);
        if ((tick + node) % period == 0) net.send(protocol::broadcast, "bench", {});
        auto app = net.take_delivered().size();
        mine.app_total += app;
        if (marks.steady(tick)) mine.app_steady += app;
        for (auto& out : net.take_outgoing())
          if (const auto* l = mine.to(out.neighbour))
            self->state.outbox.add(l->id, l->handle, l->peer, tick, std::move(out.message));
        net.take_changes();
        net.take_failures();
      });
}

struct node_plan {
  bool network = false;  // node_network mode
  int burst = 1;
  std::int64_t lookahead = 1;
  std::int64_t period = 15;  // node_network: ticks between a node's own broadcasts
};

caf::behavior bench_node(node_actor* self, int node, node_plan plan,
                         std::shared_ptr<node_links> mine, std::shared_ptr<steady_marks> marks,
                         std::shared_ptr<const config::scenario> scenario) {
  self->state.outbox = link_outbox{plan.lookahead};
  if (plan.network) {
    std::vector<int> attached;
    for (const auto& l : mine->links) attached.push_back(l.neighbour);
    self->state.network = std::make_unique<protocol::node_network>(node, attached, *scenario);
  }
  auto turn_when_ready = [=] {
    auto t = self->state.arrivals.take_ready();
    if (!t) return;
    if (plan.network)
      flood(self, node, plan.period, *mine, *t, *marks);
    else
      blast(self, node, plan.burst, *mine, *t, *marks);
  };
  return {
      [=](net_deliver_mail& mail) {
        self->state.arrivals.put(mail);
        turn_when_ready();
      },
      [](net_retract_atom, std::uint64_t, std::int64_t) {},
      [self, node](flush_atom) {
        self->state.outbox.flush(self, node, mail_stamp{}, false, [](std::uint64_t) {});
        return done_atom_v;
      },
      [=](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t relayed) {
        self->state.arrivals.hold({tick, p, caf::actor_cast<caf::actor>(self->current_sender())},
                                  relayed);
        turn_when_ready();
      },
  };
}

// A random geometric graph: N nodes uniform in a square sized so the mean degree is ~8.
config::scenario graph(int nodes) {
  config::scenario s;
  s.run.seed = 1;
  double side = 100.0 * std::sqrt(static_cast<double>(nodes));
  // Mean degree = N * pi r^2 / side^2 = 8.
  s.network.communication_range_m = side * std::sqrt(8.0 / (M_PI * nodes));
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, side);
  for (int i = 1; i <= nodes; ++i) {
    config::camera_settings c;
    c.id = i;
    c.position = {u(rng), u(rng)};
    s.cameras.push_back(c);
  }
  return s;
}

struct outcome {
  double wall = 0;
  protocol::message_counts links;  // summed over every link and kind
  std::size_t link_count = 0;
  double steady_wall = 0;  // between the steady marks; 0 when the run is too short for them
  std::uint64_t read_steady = 0;
  std::uint64_t app_total = 0;
  std::uint64_t app_steady = 0;
  bool ok = false;
};

outcome run_links(const config::scenario& s, const protocol::topology& topo, unsigned threads,
                  bool own_thread, scheduling_order order, node_plan plan, std::int64_t ticks,
                  std::int64_t steady_from) {
  system_config cfg(threads, order);
  caf::actor_system sys{cfg};
  recorder_settings rs;
  rs.output_dir = std::filesystem::temp_directory_path() / "argus-link-bench";
  auto recorder = spawn_recorder(sys, rs);
  clock_settings cs;
  cs.end_tick = ticks;
  cs.own_thread = own_thread;
  auto clock = spawn_clock(sys, cs, recorder, caf::actor{});
  plan.lookahead = protocol::link_model::min_delay_ticks(s.network, s.run.tick.count());
  auto marks = std::make_shared<steady_marks>();
  marks->from_tick = steady_from;
  marks->to_tick = ticks - 1;
  auto scenario = std::make_shared<const config::scenario>(s);
  std::map<int, std::shared_ptr<node_links>> per_node;
  for (int n : topo.nodes()) per_node[n] = std::make_shared<node_links>();
  auto model = make_link_model(s);
  std::vector<caf::actor> links;
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    auto [a, b] = topo.links()[i];
    auto info = link_participant(i, a, b);
    links.push_back(spawn_link(sys, s, model, i, a, b));
    per_node[a]->links.push_back({links.back(), info.id, participant_ids::camera(b), b});
    per_node[b]->links.push_back({links.back(), info.id, participant_ids::camera(a), a});
  }
  // Nodes after their links are listed (a node_network is made with its neighbours).
  std::map<int, caf::actor> nodes;
  for (int n : topo.nodes()) {
    nodes[n] = sys.spawn(bench_node, n, plan, per_node[n], marks, scenario);
    participant_info info{participant_ids::camera(n), "n", phase::cameras, wake_mode::every_tick};
    info.flushes_at_end = true;
    caf::anon_send(clock, join_atom_v, nodes[n], info);
  }
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    auto [a, b] = topo.links()[i];
    for (int end : {a, b}) {
      link_command attach;
      attach.node = end;
      attach.handle = nodes[end];
      caf::anon_send(links[i], link_cmd_atom_v, mail_stamp{-1, 0, 0, 0}, attach);
    }
    caf::anon_send(clock, join_atom_v, links[i], link_participant(i, a, b));
  }
  outcome out;
  out.link_count = topo.links().size();
  caf::scoped_actor self{sys};
  self->request(clock, caf::infinite, start_atom_v)
      .receive(
          [&](run_result& r) {
            out.ok = true;
            out.wall = r.wall_seconds;
            for (const auto& [name, kinds] : r.links)
              for (const auto& [kind, c] : kinds) out.links += c;
          },
          [](caf::error&) {});
  for (const auto& [n, mine] : per_node) {
    out.read_steady += mine->read_steady;
    out.app_total += mine->app_total;
    out.app_steady += mine->app_steady;
  }
  if (marks->to_tick > marks->from_tick && marks->to_ns.load() != 0)
    out.steady_wall = marks->seconds();
  return out;
}

void bm_links(benchmark::State& state) {
  auto nodes = static_cast<int>(state.range(0));
  auto threads = static_cast<unsigned>(state.range(1));
  node_plan plan;
  plan.burst = static_cast<int>(state.range(2));
  bool own_thread = state.range(3) != 0;
  auto order = state.range(4) != 0 ? scheduling_order::caf_default : scheduling_order::turn_order;
  plan.network = state.range(5) != 0;
  auto s = graph(nodes);
  protocol::topology topo(s);
  const auto max_delay_ticks =
      static_cast<std::int64_t>(std::ceil(s.network.max_delay.count() / s.run.tick.count()));
  // Links: steady from the third window on (tick 2L). node_network: once every node has heard
  // every neighbour's first beacon (a hello interval plus the longest delay).
  const auto lookahead = protocol::link_model::min_delay_ticks(s.network, s.run.tick.count());
  plan.period = config::to_ticks_at_least_one(s.network.hello_interval, s.run.tick);
  const std::int64_t steady_from = plan.network ? plan.period + max_delay_ticks + 1 : 2 * lookahead;
  // At least ten lookahead windows past the steady start. The first ticks and the end of the run
  // are in `delivered_per_s`, and are a fifth of the time at 10,000 nodes; `steady_per_s` leaves
  // them out.
  std::int64_t ticks = std::clamp<std::int64_t>(2'000'000 / (8 * nodes), 30, 300);
  ticks = std::max(ticks, steady_from + 30);
  // ARGUS_LINK_BENCH_TICKS=N runs N ticks instead.
  if (const char* t = std::getenv("ARGUS_LINK_BENCH_TICKS")) ticks = std::max(1, std::atoi(t));
  double wall = 0, steady_wall = 0;
  protocol::message_counts links;
  std::uint64_t read_steady = 0, app_total = 0, app_steady = 0;
  for (auto _ : state) {
    auto o = run_links(s, topo, threads, own_thread, order, plan, ticks, steady_from);
    if (!o.ok || o.wall <= 0) {
      state.SkipWithError("the run failed: the clock reported an error");
      return;
    }
    state.SetIterationTime(o.wall);
    wall += o.wall;
    links += o.links;
    steady_wall += o.steady_wall;
    read_steady += o.read_steady;
    app_total += o.app_total;
    app_steady += o.app_steady;
    state.counters["links"] = static_cast<double>(o.link_count);
  }
  const double runs = static_cast<double>(state.iterations());
  auto rate = [](double n, double s) { return s > 0 ? n / s : 0.0; };
  state.counters["delivered_per_s"] = rate(static_cast<double>(links.delivered), wall);
  state.counters["steady_per_s"] = rate(static_cast<double>(read_steady), steady_wall);
  state.counters["accepted_per_s"] = rate(static_cast<double>(links.sent), wall);
  state.counters["accepted"] = static_cast<double>(links.sent) / runs;
  state.counters["delivered"] = static_cast<double>(links.delivered) / runs;
  state.counters["lost"] = static_cast<double>(links.lost) / runs;
  state.counters["dropped"] = static_cast<double>(links.dropped) / runs;
  state.counters["in_flight"] = static_cast<double>(links.in_flight) / runs;
  if (plan.network) {
    state.counters["app_per_s"] = rate(static_cast<double>(app_total), wall);
    state.counters["app_steady_per_s"] = rate(static_cast<double>(app_steady), steady_wall);
  }
  state.counters["ticks"] = static_cast<double>(ticks);
  state.counters["mean_degree"] = 2.0 * static_cast<double>(topo.links().size()) / nodes;
}

// With 2 workers, the clock on a worker (clock_thread 0) and on its own thread (1). At burst
// 1, CAF's scheduling order too (caf_order 1): the baseline for Argus's turn order (0). Then
// node_network nodes (mode 1) on the clock's default placement, turn order.
void link_args(benchmark::internal::Benchmark* b) {
  for (int burst : {1, 2, 4, 8})
    for (int caf_order : {0, 1})
      for (int threads : {1, 2})
        for (int own : {0, 1})
          for (int nodes : {100, 1000, 10000})
            if ((threads > 1 || own == 0) && (burst == 1 || caf_order == 0))
              b->Args({nodes, threads, burst, own, caf_order, 0});
  for (int threads : {1, 2})
    for (int nodes : {100, 1000, 10000}) b->Args({nodes, threads, 1, 0, 0, 1});
}

BENCHMARK(bm_links)
    ->Apply(link_args)
    ->ArgNames({"nodes", "threads", "burst", "clock_thread", "caf_order", "mode"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
