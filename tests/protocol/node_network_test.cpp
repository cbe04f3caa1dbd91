// The network side of camera nodes over an ideal network (no loss, one tick per hop): hop
// limit, broadcast reach, no storm, neighbour discovery.

#include "protocol/node_network.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "protocol/topology.hpp"

namespace argus::protocol {
namespace {

// Cameras 10 m apart on a line, range 15 m: 1-2-3-4-5-6, each linked to its next.
config::scenario line_of(int n) {
  config::scenario s;
  for (int i = 1; i <= n; ++i) {
    config::camera_settings c;
    c.id = i;
    c.position = {10.0 * i, 0.0};
    s.cameras.push_back(c);
  }
  s.network.communication_range_m = 15.0;
  return s;
}

struct ideal_network {
  explicit ideal_network(const config::scenario& s) : topo(s) {
    for (int n : topo.nodes()) nodes.emplace(n, node_network(n, topo.neighbours(n), s));
  }

  // One tick: every node runs, then what it sent arrives at the next tick.
  void step(std::int64_t tick) {
    for (auto& [id, node] : nodes) {
      if (down.count(id) != 0) continue;
      for (auto& [from, m] : inbox[id]) node.receive(tick, from, m);
      inbox[id].clear();
      node.tick(tick);
      for (auto& out : node.take_outgoing()) {
        ++transmissions[out.message.kind.name()];
        auto m = out.message;
        ++m.hops;
        next[out.neighbour].emplace_back(id, m);
      }
      for (auto& m : node.take_delivered()) delivered[id].push_back(m);
      for (auto& c : node.take_changes()) changes[id].push_back(c);
    }
    for (auto& [id, list] : next)
      for (auto& x : list) inbox[id].push_back(std::move(x));
    next.clear();
  }

  void run(std::int64_t from, std::int64_t to) {
    for (auto t = from; t < to; ++t) step(t);
  }

  topology topo;
  std::map<int, node_network> nodes;
  std::set<int> down;
  std::map<int, std::vector<std::pair<int, net_message>>> inbox, next;
  std::map<int, std::vector<net_message>> delivered;
  std::map<int, std::vector<neighbour_change>> changes;
  std::map<std::string, int> transmissions;
};

TEST(node_network, discovers_its_neighbours_by_hello_and_forgets_silent_ones) {
  ideal_network net(line_of(3));
  net.run(0, 30);  // two hello intervals (1 s) at 15 Hz
  EXPECT_EQ(net.nodes.at(2).live_neighbours(), (std::vector<int>{1, 3}));
  EXPECT_EQ(net.nodes.at(1).live_neighbours(), (std::vector<int>{2}));
  net.down.insert(3);
  net.run(30, 30 + 15 * 4);  // last heard at tick 28; neighbour timeout: 5 s
  EXPECT_EQ(net.nodes.at(2).live_neighbours(), (std::vector<int>{1, 3}));  // not yet
  net.run(30 + 15 * 4, 30 + 15 * 7);
  EXPECT_EQ(net.nodes.at(2).live_neighbours(), (std::vector<int>{1}));
  ASSERT_FALSE(net.changes[2].empty());
  EXPECT_EQ(net.changes[2].back().neighbour, 3);
  EXPECT_FALSE(net.changes[2].back().up);
  net.down.erase(3);  // it comes back and is heard again
  net.run(30 + 15 * 7, 30 + 15 * 9);
  EXPECT_EQ(net.nodes.at(2).live_neighbours(), (std::vector<int>{1, 3}));
}

TEST(node_network, hello_period_and_neighbour_timeout_are_the_network_settings) {
  auto s = line_of(2);
  s.network.hello_interval = config::seconds{2.0};
  s.network.neighbour_timeout = config::seconds{3.0};
  // The group protocol's heartbeat and member timeout are not the network layer's.
  s.controller.heartbeat_interval = config::seconds{0.2};
  s.controller.member_failure_timeout = config::seconds{30.0};
  ideal_network net(s);
  net.run(0, 15 * 10);
  EXPECT_EQ(net.transmissions["hello"], 2 * 5);  // each of two nodes every 30 ticks
  net.down.insert(2);
  const auto before = net.changes[1].size();
  net.run(15 * 10, 15 * 10 + 45);  // last heard at tick 149: given up after 45 ticks more
  EXPECT_EQ(net.changes[1].size(), before);
  net.run(15 * 10 + 45, 15 * 10 + 45 + 30);
  EXPECT_EQ(net.nodes.at(1).live_neighbours(), (std::vector<int>{}));
}

TEST(node_network, unicast_reaches_a_node_three_hops_away_but_not_four) {
  ideal_network net(line_of(6));
  net.run(0, 30);
  net.nodes.at(1).send(4, "ping", "three hops");
  net.nodes.at(1).send(5, "ping", "four hops");
  net.run(30, 60);
  ASSERT_EQ(net.delivered[4].size(), 1u);
  EXPECT_EQ(net.delivered[4][0].body, "three hops");
  EXPECT_EQ(net.delivered[4][0].hops, 3);
  EXPECT_TRUE(net.delivered[5].empty());
  // Nodes on the way forward it but do not consume it.
  EXPECT_TRUE(net.delivered[2].empty());
  EXPECT_TRUE(net.delivered[3].empty());
}

TEST(node_network, broadcast_reaches_exactly_the_nodes_within_the_hop_limit) {
  ideal_network net(line_of(6));
  net.run(0, 30);
  net.nodes.at(2).send(broadcast, "query", "");
  net.run(30, 60);
  std::set<int> got;
  for (auto& [id, list] : net.delivered)
    for (auto& m : list)
      if (m.kind == "query") got.insert(id);
  EXPECT_EQ(got, (std::set<int>{1, 3, 4, 5}));  // 6 is four hops from 2
}

TEST(node_network, flooding_sends_each_message_at_most_once_per_link_direction) {
  // A full mesh of 8 nodes: the worst case for a storm.
  auto s = line_of(8);
  s.network.communication_range_m = 1000.0;
  ideal_network net(s);
  net.run(0, 30);
  net.transmissions.clear();
  net.nodes.at(1).send(broadcast, "query", "");
  net.run(30, 60);
  // 28 links, two directions: never more than 56 transmissions, whatever the hop limit.
  EXPECT_LE(net.transmissions["query"], 56);
  std::size_t receivers = 0;
  for (auto& [id, list] : net.delivered) receivers += list.size();
  EXPECT_EQ(receivers, 7u);  // once each, duplicates suppressed
}

TEST(node_network, a_request_unanswered_within_the_message_timeout_marks_the_peer_failed) {
  ideal_network net(line_of(4));
  net.run(0, 30);
  // Answered: node 3 replies to whatever node 1 asks.
  auto asked = net.nodes.at(1).request(30, 3, "ping", "");
  for (std::int64_t t = 30; t < 60; ++t) {
    net.step(t);
    for (auto& m : net.delivered[3])
      if (m.kind == "ping") net.nodes.at(3).reply(m, "pong", "");
    net.delivered[3].clear();
  }
  EXPECT_TRUE(net.nodes.at(1).take_failures().empty());
  ASSERT_FALSE(net.delivered[1].empty());
  EXPECT_EQ(net.delivered[1].back().reply_to, asked);
  // Unanswered: node 4 is down; 1500 ms at 15 Hz is 22.5 ticks, rounded to 23.
  net.down.insert(4);
  auto lost = net.nodes.at(1).request(60, 4, "ping", "");
  net.run(60, 60 + 23);
  EXPECT_TRUE(net.nodes.at(1).take_failures().empty());
  net.run(60 + 23, 60 + 25);
  auto failures = net.nodes.at(1).take_failures();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].peer, 4);
  EXPECT_EQ(failures[0].request, lost);
}

// Cameras on a 3 x 3 grid 10 m apart, range 12 m: each linked to the cameras beside it, not
// to those diagonally across (14 m).
//   7 8 9
//   4 5 6
//   1 2 3
config::scenario grid_3x3(config::unicast_routing unicast) {
  config::scenario s;
  for (int i = 1; i <= 9; ++i) {
    config::camera_settings c;
    c.id = i;
    c.position = {10.0 * ((i - 1) % 3), 10.0 * ((i - 1) / 3)};
    s.cameras.push_back(c);
  }
  s.network.communication_range_m = 12.0;
  s.network.unicast = unicast;
  return s;
}

// Node 1 floods a query; node 6, three hops away, answers it. Returns the answer's
// transmissions and whether node 1 got it.
std::pair<int, bool> answer_to_a_flood(ideal_network& net, std::int64_t from) {
  net.nodes.at(1).send(broadcast, "query", "");
  net.run(from, from + 10);
  EXPECT_FALSE(net.delivered[6].empty());
  if (net.delivered[6].empty()) return {0, false};
  net.transmissions.clear();
  net.delivered[1].clear();
  net.nodes.at(6).reply(net.delivered[6].back(), "answer", "");
  net.delivered[6].clear();
  net.run(from + 10, from + 20);
  bool got = false;
  for (const auto& m : net.delivered[1]) got = got || m.kind == "answer";
  return {net.transmissions["answer"], got};
}

TEST(node_network, reverse_path_routing_sends_an_answer_back_along_the_querys_path) {
  ideal_network flooded(grid_3x3(config::unicast_routing::flood));
  flooded.run(0, 30);
  const auto [flood_cost, flood_got] = answer_to_a_flood(flooded, 30);
  ideal_network routed(grid_3x3(config::unicast_routing::reverse_path));
  routed.run(0, 30);
  const auto [routed_cost, routed_got] = answer_to_a_flood(routed, 30);
  EXPECT_TRUE(flood_got);
  EXPECT_TRUE(routed_got);
  EXPECT_EQ(routed_cost, 3);  // one link per hop
  EXPECT_GT(flood_cost, 3);   // the flood covers the grid within three hops
}

TEST(node_network, reverse_path_routing_floods_when_the_routes_next_hop_is_gone) {
  auto s = grid_3x3(config::unicast_routing::reverse_path);
  s.network.max_hops = 5;  // 6-9-8-7-4-1, the way round, is five hops
  ideal_network net(s);
  net.run(0, 30);
  net.nodes.at(1).send(broadcast, "query", "");
  net.run(30, 40);
  ASSERT_FALSE(net.delivered[6].empty());
  const net_message query = net.delivered[6].back();
  // The query came to node 6 through 3 or 5; both fail, and node 6 gives them up.
  net.down.insert(3);
  net.down.insert(5);
  net.run(40, 40 + 15 * 7);
  ASSERT_EQ(net.nodes.at(6).live_neighbours(), (std::vector<int>{9}));
  net.delivered[1].clear();
  net.nodes.at(6).reply(query, "answer", "");
  net.run(40 + 15 * 7, 40 + 15 * 8);
  bool got = false;
  for (const auto& m : net.delivered[1]) got = got || m.kind == "answer";
  EXPECT_TRUE(got);
}

}  // namespace
}  // namespace argus::protocol
