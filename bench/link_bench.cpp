// Messages per second through the link layer (issue #6): N nodes in a random geometric graph
// with mean degree about 8; every node sends K messages per tick on each of its links (K = 1:
// the worst case for batching; K = 2, 4, 8: bursts such as a query to every neighbour plus
// forwarding) through an outbox, as camera nodes do; links draw Table 2 delay and loss and
// deliver; every node reads what arrives, as a camera node does. 1 and 2 scheduler threads;
// with 2, the clock on a worker and on its own thread. At burst 1, under CAF's scheduling order
// as well as Argus's turn order (actors/turn_order_scheduling.hpp).
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
#include "protocol/link_model.hpp"
#include "protocol/topology.hpp"

namespace {

using namespace argus;
using namespace argus::actors;

struct node_links {
  struct entry {
    caf::actor handle;
    std::uint64_t id;    // the link's participant id
    std::uint64_t peer;  // the other end's participant id
  };
  std::vector<entry> links;
};

// When the first node took its turn in two ticks: the steady part of a run lies between them,
// past the first ticks (every link joins, the first windows go out) and before the end (every
// node flushes, every link reports).
struct steady_marks {
  std::int64_t from_tick = 0;
  std::int64_t to_tick = 0;
  std::atomic<std::int64_t> from_ns{0};
  std::atomic<std::int64_t> to_ns{0};

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

struct blaster_state {
  std::uint32_t seq = 0;
  link_outbox outbox{1};
  net_arrivals arrivals;
  std::uint64_t read = 0;
};

using blaster_actor = caf::stateful_actor<blaster_state>;

// Interned once, as a node's protocol would: a kind made from its name takes a lock.
const protocol::message_kind bench_kind{"bench"};

// One turn: read what is due, as a camera node does, then send `burst` messages on each link.
void blast(blaster_actor* self, int node, int burst, const node_links& mine,
           const net_arrivals::turn& t, steady_marks& marks) {
  auto& st = self->state;
  marks.mark(t.tick);
  tick_context ctx(participant_ids::camera(node), "n", t.tick, phase::cameras);
  // Each message read, as a camera reads it: its header, to decide what it is.
  st.arrivals.for_each_due(t.tick, t.phase, [&](const mail_stamp&, int, protocol::net_message& m) {
    st.read += m.id != 0 && !m.kind.empty();
  });
  for (const auto& l : mine.links) {
    for (int i = 0; i < burst; ++i) {
      protocol::net_message m;
      m.id = protocol::make_message_id(node, st.seq++);
      m.origin = node;
      m.kind = bench_kind;
      st.outbox.add(l.id, l.handle, l.peer, t.tick, std::move(m));
    }
  }
  mail_stamp now{t.tick, t.phase, participant_ids::camera(node), 0};
  if (st.outbox.window_ends(t.tick))
    st.outbox.flush(self, node, now, true, [&](std::uint64_t peer) { ctx.relayed_to(peer); });
  self->send(t.clock, std::move(ctx).finish());
}

// Sends `burst` messages per link per tick through an outbox, as a camera node does, and
// reads what its links hand over; counts nothing itself (the links account).
caf::behavior blaster(blaster_actor* self, int node, int burst, std::int64_t lookahead,
                      std::shared_ptr<node_links> mine, std::shared_ptr<steady_marks> marks) {
  self->state.outbox = link_outbox{lookahead};
  auto turn_when_ready = [=] {
    if (auto t = self->state.arrivals.take_ready()) blast(self, node, burst, *mine, *t, *marks);
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
  std::uint64_t messages = 0;
  std::size_t links = 0;
  double steady_wall = 0;  // between the steady marks; 0 when the run is too short for them
  std::uint64_t steady_messages = 0;
};

outcome run_links(const config::scenario& s, const protocol::topology& topo, unsigned threads,
                  bool own_thread, scheduling_order order, int burst, std::int64_t ticks) {
  system_config cfg(threads, order);
  caf::actor_system sys{cfg};
  recorder_settings rs;
  rs.output_dir = std::filesystem::temp_directory_path() / "argus-link-bench";
  auto recorder = spawn_recorder(sys, rs);
  clock_settings cs;
  cs.end_tick = ticks;
  cs.own_thread = own_thread;
  auto clock = spawn_clock(sys, cs, recorder, caf::actor{});
  auto lookahead = protocol::link_model::min_delay_ticks(s.network, s.run.tick.count());
  // Steady from the third window on, to the last tick.
  auto marks = std::make_shared<steady_marks>();
  marks->from_tick = 2 * lookahead;
  marks->to_tick = ticks - 1;
  std::map<int, std::shared_ptr<node_links>> per_node;
  std::map<int, caf::actor> nodes;
  for (int n : topo.nodes()) per_node[n] = std::make_shared<node_links>();
  for (int n : topo.nodes()) {
    nodes[n] = sys.spawn(blaster, n, burst, lookahead, per_node[n], marks);
    participant_info info{participant_ids::camera(n), "n", phase::cameras, wake_mode::every_tick};
    info.flushes_at_end = true;
    caf::anon_send(clock, join_atom_v, nodes[n], info);
  }
  auto model = make_link_model(s);
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    auto [a, b] = topo.links()[i];
    auto info = link_participant(i, a, b);
    auto link = spawn_link(sys, s, model, i, a, b);
    per_node[a]->links.push_back({link, info.id, participant_ids::camera(b)});
    per_node[b]->links.push_back({link, info.id, participant_ids::camera(a)});
    for (int end : {a, b}) {
      link_command attach;
      attach.node = end;
      attach.handle = nodes[end];
      caf::anon_send(link, link_cmd_atom_v, mail_stamp{-1, 0, 0, 0}, attach);
    }
    caf::anon_send(clock, join_atom_v, link, info);
  }
  outcome out;
  out.links = topo.links().size();
  caf::scoped_actor self{sys};
  self->request(clock, caf::infinite, start_atom_v)
      .receive(
          [&](run_result& r) {
            out.wall = r.wall_seconds;
            for (const auto& [name, kinds] : r.links)
              for (const auto& [kind, c] : kinds) out.messages += c.sent;
          },
          [](caf::error&) {});
  if (marks->to_tick > marks->from_tick && marks->to_ns.load() != 0) {
    out.steady_wall = marks->seconds();
    // Every node sends `burst` messages on each of its links in every turn.
    out.steady_messages = static_cast<std::uint64_t>(marks->to_tick - marks->from_tick) *
                          static_cast<std::uint64_t>(burst) * 2 * out.links;
  }
  return out;
}

void bm_links(benchmark::State& state) {
  auto nodes = static_cast<int>(state.range(0));
  auto threads = static_cast<unsigned>(state.range(1));
  auto burst = static_cast<int>(state.range(2));
  bool own_thread = state.range(3) != 0;
  auto order = state.range(4) != 0 ? scheduling_order::caf_default : scheduling_order::turn_order;
  auto s = graph(nodes);
  protocol::topology topo(s);
  // At least 30 ticks (ten lookahead windows). The first tick (every link joins) and the end of
  // the run (every node flushes, every link reports) are in `messages_per_s`, and are a fifth
  // of the time at 10,000 nodes; `steady_per_s` leaves them out.
  std::int64_t ticks = std::clamp<std::int64_t>(2'000'000 / (8 * nodes), 30, 300);
  // ARGUS_LINK_BENCH_TICKS=N runs N ticks instead (two lengths give the steady-state rate
  // too, as a check on `steady_per_s`).
  if (const char* t = std::getenv("ARGUS_LINK_BENCH_TICKS")) ticks = std::max(1, std::atoi(t));
  double wall = 0, steady_wall = 0;
  std::uint64_t messages = 0, steady_messages = 0;
  for (auto _ : state) {
    auto o = run_links(s, topo, threads, own_thread, order, burst, ticks);
    state.SetIterationTime(o.wall);
    wall += o.wall;
    messages += o.messages;
    steady_wall += o.steady_wall;
    steady_messages += o.steady_messages;
    state.counters["links"] = static_cast<double>(o.links);
  }
  // The whole run, first tick and end included.
  state.counters["messages_per_s"] = wall > 0 ? static_cast<double>(messages) / wall : 0;
  // Between the first node's turns in tick 2L and in the last tick: the rate the link layer
  // keeps up once running, without the joining and the final reports.
  state.counters["steady_per_s"] =
      steady_wall > 0 ? static_cast<double>(steady_messages) / steady_wall : 0;
  state.counters["mean_degree"] = 2.0 * static_cast<double>(topo.links().size()) / nodes;
}

// With 2 workers, the clock on a worker (clock_thread 0) and on its own thread (1). At burst
// 1, CAF's scheduling order too (caf_order 1): the baseline for Argus's turn order (0).
void link_args(benchmark::internal::Benchmark* b) {
  for (int burst : {1, 2, 4, 8})
    for (int caf_order : {0, 1})
      for (int threads : {1, 2})
        for (int own : {0, 1})
          for (int nodes : {100, 1000, 10000})
            if ((threads > 1 || own == 0) && (burst == 1 || caf_order == 0))
              b->Args({nodes, threads, burst, own, caf_order});
}

BENCHMARK(bm_links)
    ->Apply(link_args)
    ->ArgNames({"nodes", "threads", "burst", "clock_thread", "caf_order"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
