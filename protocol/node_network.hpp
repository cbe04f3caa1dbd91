#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "config/scenario.hpp"
#include "protocol/flood_router.hpp"
#include "protocol/net_message.hpp"

namespace argus::protocol {

/// One message to put on the link to `neighbour`.
struct outgoing_message {
  int neighbour = 0;
  net_message message;
};

/// A neighbour came up (first heard, or heard again after it was given up) or was lost.
struct neighbour_change {
  int neighbour = 0;
  bool up = false;
};

/// A request that got no answer within the message timeout: its peer is taken as failed
/// (Section IV-C: "communication failures are perceived as camera failures").
struct peer_failure {
  int peer = 0;
  std::uint64_t request = 0;
  std::string kind;
};

/// A camera node's view of the network, with no knowledge of positions or of the graph beyond
/// its own links: neighbour discovery by `hello` beacons (one hop, every network
/// `hello_interval`), liveness by what it hears (a neighbour unheard for the network's
/// `neighbour_timeout` is given up, as Section IV-C treats silence as failure), and multi-hop
/// delivery by `flood_router` over the live neighbours. The actor feeds it what arrived and
/// ferries what it wants sent.
class node_network {
 public:
  /// `attached` are the nodes at the other end of this node's links.
  node_network(int self, std::vector<int> attached, const config::scenario& scenario);

  /// A message that arrived over the link from `from`, at `tick`.
  void receive(std::int64_t tick, int from, const net_message& m);

  /// Per-tick work after the arrivals: give up silent neighbours, send the hello beacon.
  void tick(std::int64_t tick);

  /// Sends `kind`/`body` from this node to `destination` (or `broadcast`); returns its id.
  std::uint64_t send(int destination, std::string kind, std::string body);

  /// Sends a request that expects an answer from `destination` within the message timeout
  /// (Table 2: 1500 ms); if none comes, `take_failures()` reports the peer. Returns its id.
  std::uint64_t request(std::int64_t tick, int destination, std::string kind, std::string body);

  /// Answers `request` (a delivered message) with `kind`/`body`.
  std::uint64_t reply(const net_message& request, std::string kind, std::string body);

  /// What to put on links since the last call.
  std::vector<outgoing_message> take_outgoing();
  /// Messages for this node's controller since the last call (hellos are consumed here).
  std::vector<net_message> take_delivered();
  /// Neighbour changes since the last call.
  std::vector<neighbour_change> take_changes();
  /// Requests that timed out since the last call.
  std::vector<peer_failure> take_failures();

  /// Live neighbours, sorted.
  const std::vector<int>& live_neighbours() const noexcept { return live_; }

  /// Messages suppressed as duplicates so far.
  std::uint64_t duplicates_suppressed() const noexcept { return router_.duplicates_suppressed(); }

 private:
  void heard(std::int64_t tick, int neighbour);
  void refresh_live();
  void route(const net_message& m, const routing_decision& d);

  int self_;
  std::vector<int> attached_;
  flood_router router_;
  std::uint8_t max_hops_;
  std::int64_t hello_ticks_;
  std::int64_t silence_ticks_;
  std::int64_t timeout_ticks_;
  struct open_request {
    int peer = 0;
    std::int64_t deadline = 0;
    std::string kind;
  };
  std::map<std::uint64_t, open_request> open_requests_;
  std::vector<peer_failure> failures_;
  std::uint32_t next_seq_ = 0;
  std::map<int, std::int64_t> last_heard_;
  std::vector<int> live_;
  std::vector<outgoing_message> outgoing_;
  std::vector<net_message> delivered_;
  std::vector<neighbour_change> changes_;
};

}  // namespace argus::protocol
