// Messages per second through the link layer (issue #6): N nodes in a random geometric graph
// with mean degree about 8; every node sends K messages per tick on each of its links (K = 1:
// the worst case for batching; K = 2, 4, 8: bursts such as a query to every neighbour plus
// forwarding) through an outbox, as camera nodes do; links draw Table 2 delay and loss and
// deliver. 1 and 2 scheduler threads; with 2, the clock on a worker and on its own thread.
//
//   build/bench/link_bench --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "actors/clock.hpp"
#include "actors/link.hpp"
#include "actors/link_command.hpp"
#include "actors/link_outbox.hpp"
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
  std::vector<std::pair<caf::actor, std::uint64_t>> links;
};

struct blaster_state {
  std::uint32_t seq = 0;
  std::uint64_t mail_seq = 0;
  link_outbox outbox{1};
};

// Sends `burst` messages per link per tick through an outbox, as a camera node does; counts
// nothing itself (the links account).
caf::behavior blaster(caf::stateful_actor<blaster_state>* self, int node, int burst,
                      std::int64_t lookahead, std::shared_ptr<node_links> mine) {
  self->state.outbox = link_outbox{lookahead};
  return {
      [](net_deliver_atom, const mail_stamp&, int, const std::vector<net_delivery>&) {
        // nop: arrivals are the links' business here
      },
      [](net_retract_atom, std::uint64_t, std::int64_t) {},
      [self, node](flush_atom) {
        self->state.outbox.flush(self, node, [](std::uint64_t) {});
        return done_atom_v;
      },
      [=](tick_atom, std::int64_t tick, std::uint8_t) {
        auto& st = self->state;
        tick_context ctx(participant_ids::camera(node), "n", tick, phase::cameras);
        for (const auto& [link, id] : mine->links) {
          std::vector<protocol::net_message> batch(static_cast<std::size_t>(burst));
          for (auto& m : batch) {
            m.id = protocol::make_message_id(node, st.seq++);
            m.origin = node;
            m.kind = "bench";
          }
          st.outbox.add(id, link, mail_stamp{tick, 3, participant_ids::camera(node), st.mail_seq++},
                        std::move(batch));
        }
        if (st.outbox.window_ends(tick))
          st.outbox.flush(self, node, [&](std::uint64_t id) { ctx.sent_mail_to(id); });
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ctx).finish());
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
};

outcome run_links(const config::scenario& s, const protocol::topology& topo, unsigned threads,
                  bool own_thread, int burst, std::int64_t ticks) {
  system_config cfg(threads);
  caf::actor_system sys{cfg};
  recorder_settings rs;
  rs.output_dir = std::filesystem::temp_directory_path() / "argus-link-bench";
  auto recorder = spawn_recorder(sys, rs);
  clock_settings cs;
  cs.end_tick = ticks;
  cs.own_thread = own_thread;
  auto clock = spawn_clock(sys, cs, recorder, caf::actor{});
  auto lookahead = protocol::link_model::min_delay_ticks(s.network, s.run.tick.count());
  std::map<int, std::shared_ptr<node_links>> per_node;
  std::map<int, caf::actor> nodes;
  for (int n : topo.nodes()) per_node[n] = std::make_shared<node_links>();
  for (int n : topo.nodes()) {
    nodes[n] = sys.spawn(blaster, n, burst, lookahead, per_node[n]);
    participant_info info{participant_ids::camera(n), "n", phase::cameras, wake_mode::every_tick};
    info.flushes_at_end = true;
    caf::anon_send(clock, join_atom_v, nodes[n], info);
  }
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    auto [a, b] = topo.links()[i];
    auto info = link_participant(i, a, b);
    auto link = spawn_link(sys, s, i, a, b);
    per_node[a]->links.emplace_back(link, info.id);
    per_node[b]->links.emplace_back(link, info.id);
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
  return out;
}

void bm_links(benchmark::State& state) {
  auto nodes = static_cast<int>(state.range(0));
  auto threads = static_cast<unsigned>(state.range(1));
  auto burst = static_cast<int>(state.range(2));
  bool own_thread = state.range(3) != 0;
  auto s = graph(nodes);
  protocol::topology topo(s);
  std::int64_t ticks = std::clamp<std::int64_t>(400'000 / (8 * nodes), 5, 200);
  double wall = 0;
  std::uint64_t messages = 0;
  for (auto _ : state) {
    auto o = run_links(s, topo, threads, own_thread, burst, ticks);
    state.SetIterationTime(o.wall);
    wall += o.wall;
    messages += o.messages;
    state.counters["links"] = static_cast<double>(o.links);
  }
  state.counters["messages_per_s"] = wall > 0 ? static_cast<double>(messages) / wall : 0;
  state.counters["mean_degree"] = 2.0 * static_cast<double>(topo.links().size()) / nodes;
}

// With 2 workers, the clock on a worker (clock_thread 0) and on its own thread (1).
void link_args(benchmark::internal::Benchmark* b) {
  for (int burst : {1, 2, 4, 8})
    for (int threads : {1, 2})
      for (int own : {0, 1})
        for (int nodes : {100, 1000, 10000})
          if (threads > 1 || own == 0) b->Args({nodes, threads, burst, own});
}

BENCHMARK(bm_links)
    ->Apply(link_args)
    ->ArgNames({"nodes", "threads", "burst", "clock_thread"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
