#define CAF_SUITE actors.network

// The whole network of camera nodes and link actors under CAF's deterministic test
// coordinator: hop limit, broadcast reach, request time-outs and neighbour discovery through
// crashes, with Table 2 delays (3 to 7 ticks per link) and the real clock.

#include <functional>
#include <map>
#include <queue>
#include <random>
#include <set>

#include "actors/clock.hpp"
#include "actors/fault_injector.hpp"
#include "actors/network_assembly.hpp"
#include "actors/participant_ids.hpp"
#include "actors/system_config.hpp"
#include "caf/test/dsl.hpp"
#include "caf/test/unit_test_impl.hpp"
#include "fmt/format.h"
#include "protocol/topology.hpp"
#include "tests/actors/recording_fixture.hpp"

using namespace argus;
using namespace argus::actors;
using namespace argus::actors::testing;

namespace {

// One message a camera is asked to originate at a tick.
struct origination {
  int camera = 0;
  int destination = protocol::broadcast;
  std::string kind;
  bool expects_reply = false;
};

constexpr std::uint64_t operator_id = 10;

// Asks camera nodes to send messages, in the faults phase, as a controller would.
caf::behavior operator_participant(caf::event_based_actor* self, std::map<int, caf::actor> cameras,
                                   std::multimap<std::int64_t, origination> plan) {
  auto seq = std::make_shared<std::uint64_t>(0);
  return {
      [=](tick_atom, std::int64_t tick, std::uint8_t, std::uint32_t) {
        tick_context ctx(operator_id, "operator", tick, phase::faults);
        auto [first, last] = plan.equal_range(tick);
        for (auto it = first; it != last; ++it) {
          const auto& o = it->second;
          self->send(cameras.at(o.camera), net_originate_atom_v,
                     mail_stamp{tick, 0, operator_id, (*seq)++}, o.destination, o.kind,
                     std::string{}, o.expects_reply);
          ctx.sent_mail_to(participant_ids::camera(o.camera));
        }
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ctx).finish());
      },
  };
}

struct fixture : recording_fixture {
  // Runs `scenario` for `ticks` with the operator's plan; the fault injector applies the
  // scenario's faults.
  void run_network(const config::scenario& scenario, std::int64_t ticks,
                   std::multimap<std::int64_t, origination> plan) {
    clock_settings cs;
    cs.end_tick = ticks;
    cs.tick_seconds = scenario.run.tick.count();
    auto clock = spawn_clock(sys, cs, recorder, caf::actor{});
    auto net = spawn_network(sys, scenario, protocol::topology(scenario), clock);
    auto op = sys.spawn(operator_participant, net.cameras, std::move(plan));
    self->send(clock, join_atom_v, op,
               participant_info{operator_id, "operator", phase::faults, wake_mode::every_tick});
    auto faults = spawn_fault_injector(sys, scenario, clock, std::move(net));
    self->send(clock, join_atom_v, faults, fault_injector_participant(scenario));
    self->send(clock, start_atom_v);
    run();
    CAF_REQUIRE(rec->done);
  }

  // The events of `kind` whose fields contain `fields`.
  std::vector<sim_event> events(const std::string& kind, const std::string& fields = {}) const {
    std::vector<sim_event> out;
    for (const auto& ev : rec->events)
      if (ev.kind == kind && ev.fields_json.find(fields) != std::string::npos) out.push_back(ev);
    return out;
  }

  // Cameras that received `message` from `origin`.
  std::set<int> receivers(int origin, const std::string& message) const {
    std::set<int> out;
    for (const auto& ev :
         events("net_received", fmt::format(R"("origin":{},"message":"{}")", origin, message))) {
      auto at = ev.fields_json.find("\"camera\":");
      out.insert(std::stoi(ev.fields_json.substr(at + 9)));
    }
    return out;
  }
};

config::scenario lossless(std::vector<std::pair<double, double>> positions, double range) {
  config::scenario s;
  s.run.seed = 3;
  s.network.loss_probability = 0.0;
  s.network.communication_range_m = range;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    config::camera_settings c;
    c.id = static_cast<int>(i) + 1;
    c.position = {positions[i].first, positions[i].second};
    s.cameras.push_back(c);
  }
  return s;
}

// Six cameras in a line, 20 m apart, range 25 m: camera k is k - 1 hops from camera 1.
config::scenario line_of_six() {
  std::vector<std::pair<double, double>> at;
  for (int i = 0; i < 6; ++i) at.emplace_back(20.0 * i, 0.0);
  return lossless(at, 25.0);
}

// Hop distances from `origin` over the scenario's links.
std::map<int, int> hop_distances(const config::scenario& s, int origin) {
  protocol::topology topo(s);
  std::map<int, std::vector<int>> adjacent;
  for (auto [a, b] : topo.links()) {
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  }
  std::map<int, int> dist{{origin, 0}};
  std::queue<int> todo;
  todo.push(origin);
  while (!todo.empty()) {
    int n = todo.front();
    todo.pop();
    for (int m : adjacent[n])
      if (dist.emplace(m, dist[n] + 1).second) todo.push(m);
  }
  return dist;
}

}  // namespace

CAF_TEST_FIXTURE_SCOPE(network_tests, fixture)

CAF_TEST(a unicast crosses at most max_hops links and a broadcast stops there) {
  auto s = line_of_six();
  // Hellos go out every second: by tick 45 (3 s) every node knows its neighbours.
  run_network(
      s, 150,
      {{45, {1, 4, "to-four"}}, {45, {1, 5, "to-five"}}, {45, {1, protocol::broadcast, "to-all"}}});
  CAF_CHECK_EQUAL(receivers(1, "to-four"), (std::set<int>{4}));
  auto four = events("net_received", R"("origin":1,"message":"to-four","hops":3)");
  CAF_CHECK_EQUAL(four.size(), 1u);
  CAF_CHECK(receivers(1, "to-five").empty());  // four hops away: beyond Table 2's limit
  CAF_CHECK_EQUAL(receivers(1, "to-all"), (std::set<int>{2, 3, 4}));
  for (int k = 2; k <= 4; ++k)
    CAF_CHECK_EQUAL(
        events("net_received",
               fmt::format(R"("camera":{},"origin":1,"message":"to-all","hops":{})", k, k - 1))
            .size(),
        1u);
}

CAF_TEST(a broadcast reaches exactly the nodes within the hop limit) {
  // 40 cameras uniform in a 200 m square, range 45 m: a random geometric graph.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 200.0);
  std::vector<std::pair<double, double>> at;
  for (int i = 0; i < 40; ++i) at.emplace_back(u(rng), u(rng));
  auto s = lossless(at, 45.0);
  std::multimap<std::int64_t, origination> plan;
  for (int origin : {1, 2, 3}) plan.emplace(60, origination{origin, protocol::broadcast, "all"});
  run_network(s, 200, plan);
  for (int origin : {1, 2, 3}) {
    std::set<int> within, beyond;
    for (auto [node, d] : hop_distances(s, origin)) {
      if (d >= 1 && d <= 3) within.insert(node);
      if (d > 3) beyond.insert(node);
    }
    CAF_MESSAGE("origin " << origin << ": " << within.size() << " within 3 hops, " << beyond.size()
                          << " beyond");
    CAF_CHECK(!within.empty());
    CAF_CHECK(!beyond.empty());
    CAF_CHECK_EQUAL(receivers(origin, "all"), within);
  }
}

CAF_TEST(an unanswered request marks its peer failed after the message timeout) {
  auto s = line_of_six();
  config::fault crash;
  crash.at = config::seconds{4.0};  // tick 60
  crash.kind = config::fault_kind::crash;
  crash.camera = 2;
  s.faults = {crash};
  // A ping to a neighbour is answered before the crash (a round trip takes 6 to 14 ticks) and
  // goes unanswered after it. (Two hops away, a round trip can take 28 ticks: longer than the
  // timeout, so Table 2's parameters make a distant peer look failed now and then.)
  run_network(s, 150, {{45, {1, 2, "ping", true}}, {75, {1, 2, "ping", true}}});
  CAF_CHECK_EQUAL(receivers(2, "pong"), (std::set<int>{1}));
  auto failed = events("peer_failed", R"("camera":1,"peer":2)");
  CAF_REQUIRE_EQUAL(failed.size(), 1u);
  // Table 2: 1500 ms at 15 Hz is 22.5 ticks: an answer read 22 ticks after the request is in
  // time, so the peer is declared failed on the 23rd.
  CAF_CHECK_EQUAL(failed.front().tick, 75 + 23);
}

CAF_TEST(a cut link partitions the network and a heal reunites it) {
  auto s = line_of_six();
  config::fault cut;
  cut.at = config::seconds{1.0};  // tick 15
  cut.kind = config::fault_kind::link_cut;
  cut.camera = 3;
  cut.peer = 4;
  auto heal = cut;
  heal.at = config::seconds{4.0};  // tick 60: 45 ticks, within the neighbour timeout (75)
  heal.kind = config::fault_kind::link_heal;
  s.faults = {cut, heal};
  // The line 1-2-3-4-5-6 has no other way round: cut between 3 and 4, camera 1's broadcast
  // (3 hops) stops at 3; healed, it reaches 4 again.
  run_network(s, 120,
              {{30, {1, protocol::broadcast, "cut", false}},
               {70, {1, protocol::broadcast, "healed", false}}});
  CAF_CHECK_EQUAL(receivers(1, "cut"), (std::set<int>{2, 3}));
  CAF_CHECK_EQUAL(receivers(1, "healed"), (std::set<int>{2, 3, 4}));
}

CAF_TEST(what a camera sent before it crashed still reaches its neighbours) {
  auto s = line_of_six();
  config::fault crash;
  crash.at = config::seconds{61.0 / 15.0};  // tick 61
  crash.kind = config::fault_kind::crash;
  crash.camera = 2;
  s.faults = {crash};
  // Sent at tick 60, the first of a lookahead window (60 to 62): still in camera 2's outbox
  // when it crashes at 61, and on the wire all the same.
  run_network(s, 100, {{60, {2, protocol::broadcast, "memo", false}}});
  CAF_CHECK_EQUAL(receivers(2, "memo"), (std::set<int>{1, 3, 4, 5}));
}

CAF_TEST(neighbours are given up after a crash and found again after recovery) {
  auto s = line_of_six();
  config::fault outage;
  outage.at = config::seconds{4.0};
  outage.kind = config::fault_kind::crash_and_recover;
  outage.camera = 3;
  outage.length = config::seconds{10.0};
  s.faults = {outage};
  run_network(s, 20 * 15, {});
  for (int neighbour : {2, 4}) {
    auto lost = events("neighbour_lost", fmt::format(R"("camera":{},"neighbour":3)", neighbour));
    auto up = events("neighbour_up", fmt::format(R"("camera":{},"neighbour":3)", neighbour));
    CAF_REQUIRE_EQUAL(lost.size(), 1u);
    CAF_REQUIRE_EQUAL(up.size(), 2u);  // at start, and after the recovery at 14 s
    // Given up after the network's neighbour_timeout (5 s) of silence, before the recovery.
    CAF_CHECK_GREATER(lost.front().tick, 4 * 15 + 5 * 15 - 15);
    CAF_CHECK_LESS(lost.front().tick, 14 * 15);
    CAF_CHECK_GREATER_OR_EQUAL(up.back().tick, 14 * 15);
  }
  // The recovered node finds its neighbours again, empty-handed.
  CAF_CHECK_EQUAL(events("neighbour_up", R"("camera":3,)").size(), 4u);
}

CAF_TEST_FIXTURE_SCOPE_END()
