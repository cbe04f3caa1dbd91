#include "protocol/node_network.hpp"

#include <algorithm>
#include <utility>

#include "config/ticks.hpp"

namespace argus::protocol {
namespace {

// Interned once: beacons go out every hello interval from every node.
message_kind hello_kind() {
  static const message_kind kind{"hello"};
  return kind;
}

// The last tick at which an answer is still within `d` of the request: an answer read
// later has taken longer than `d`, so the peer is declared failed on the first such tick.
// Rounded down, not to the nearest tick: rounding up would wait past `d` for an answer that
// is already late (1500 ms at 1/15 s is 22.5 ticks: 22, not 23). At least 1: an answer needs
// a tick to travel.
std::int64_t last_tick_within(config::seconds d, config::seconds tick) {
  return std::max<std::int64_t>(1, config::ticks_within(d, tick));
}

}  // namespace

node_network::node_network(int self, std::vector<int> attached, const config::scenario& s)
    : self_(self),
      attached_(std::move(attached)),
      router_(self, s.network.unicast),
      max_hops_(static_cast<std::uint8_t>(std::min(255u, s.network.max_hops))),
      hello_ticks_(config::to_ticks_at_least_one(s.network.hello_interval, s.run.tick)),
      silence_ticks_(config::to_ticks_at_least_one(s.network.neighbour_timeout, s.run.tick)),
      timeout_ticks_(last_tick_within(s.network.message_timeout, s.run.tick)) {
  std::sort(attached_.begin(), attached_.end());
}

void node_network::heard(std::int64_t tick, int neighbour) {
  if (!std::binary_search(attached_.begin(), attached_.end(), neighbour)) return;
  auto [it, first] = last_heard_.try_emplace(neighbour, tick);
  it->second = tick;
  if (first) {
    changes_.push_back({neighbour, true});
    refresh_live();
  }
}

void node_network::refresh_live() {
  live_.clear();
  for (const auto& [n, t] : last_heard_) live_.push_back(n);
}

void node_network::receive(std::int64_t tick, int from, const net_message& m) {
  heard(tick, from);
  if (m.kind == hello_kind()) return;  // its whole job was to be heard
  auto d = router_.receive(m, from, live_);
  if (d.deliver && m.reply_to != 0) open_requests_.erase(m.reply_to);
  route(m, d);
}

void node_network::route(const net_message& m, const routing_decision& d) {
  if (d.deliver) delivered_.push_back(m);
  for (int n : d.forward_to) outgoing_.push_back({n, m});
}

void node_network::tick(std::int64_t tick) {
  for (auto it = open_requests_.begin(); it != open_requests_.end();) {
    if (tick > it->second.deadline) {
      failures_.push_back({it->second.peer, it->first, std::move(it->second.kind)});
      it = open_requests_.erase(it);
    } else {
      ++it;
    }
  }
  bool lost_any = false;
  for (auto it = last_heard_.begin(); it != last_heard_.end();) {
    if (tick - it->second > silence_ticks_) {
      changes_.push_back({it->first, false});
      it = last_heard_.erase(it);
      lost_any = true;
    } else {
      ++it;
    }
  }
  if (lost_any) refresh_live();
  // Beacons are spread over the interval by node id, so nodes do not all speak at once.
  if ((tick + self_) % hello_ticks_ == 0) {
    net_message hello;
    hello.id = make_message_id(self_, next_seq_++);
    hello.origin = self_;
    hello.destination = broadcast;
    hello.max_hops = 1;
    hello.kind = hello_kind();
    for (int n : attached_) outgoing_.push_back({n, hello});
  }
}

std::uint64_t node_network::send(int destination, std::string kind, std::string body) {
  net_message m;
  m.id = make_message_id(self_, next_seq_++);
  m.origin = self_;
  m.destination = destination;
  m.max_hops = max_hops_;
  m.kind = std::move(kind);
  m.body = std::move(body);
  route(m, router_.originate(m, live_));
  return m.id;
}

std::uint64_t node_network::request(std::int64_t tick, int destination, std::string kind,
                                    std::string body) {
  auto k = kind;
  auto id = send(destination, std::move(kind), std::move(body));
  open_requests_[id] = {destination, tick + timeout_ticks_, std::move(k)};
  return id;
}

std::uint64_t node_network::reply(const net_message& request, std::string kind, std::string body) {
  net_message m;
  m.id = make_message_id(self_, next_seq_++);
  m.origin = self_;
  m.destination = request.origin;
  m.max_hops = max_hops_;
  m.reply_to = request.id;
  m.kind = std::move(kind);
  m.body = std::move(body);
  route(m, router_.originate(m, live_));
  return m.id;
}

std::vector<outgoing_message> node_network::take_outgoing() {
  return std::exchange(outgoing_, {});
}
std::vector<net_message> node_network::take_delivered() {
  return std::exchange(delivered_, {});
}
std::vector<neighbour_change> node_network::take_changes() {
  return std::exchange(changes_, {});
}
std::vector<peer_failure> node_network::take_failures() {
  return std::exchange(failures_, {});
}

}  // namespace argus::protocol
