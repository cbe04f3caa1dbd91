#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "protocol/group_messages.hpp"
#include "world/rng.hpp"

namespace argus::controller {

/// Fig. 15: group merging by leader demotion, for when unique ids are not guaranteed. One per
/// leader; it knows nothing of groups, only of the other leaders of its task it negotiates
/// with. Contention is settled as in ALOHA: a collision (both sent demote) is retried after a
/// random interval drawn from the node's own seeded stream.
///
///   Case 1  met another leader m, not negotiating with anyone -> demote to m after a random
///           interval
///   Case 2  demote from m: (1) sent none          -> demoted: demoteack to m
///                          (2) sent one to m      -> demoteretry to m, demote to m later
///                          (3) sent one to other  -> demotenack to m
///   Case 3  demotenack from m -> negotiation with m over
///   Case 4  demoteack from m  -> m (and its members) joins this group
///   Case 5  demoteretry from m -> demote to m after a random interval
///
/// A negotiation that gets no answer ends after the group merge timeout (Table 2).
class demotion_negotiator {
 public:
  /// What the negotiation asks its leader to do.
  struct actions {
    /// Messages to send: (peer, step).
    std::vector<std::pair<int, protocol::demotion_step>> sends;
    /// This leader is demoted and follows this peer.
    std::optional<int> demoted_to;
    /// Peers that acknowledged their demotion (Case 4).
    std::vector<int> absorbed;
  };

  /// `backoff_max_ticks`: the random interval is uniform in [0, backoff_max_ticks] ticks.
  demotion_negotiator(std::int64_t merge_timeout_ticks, std::int64_t backoff_max_ticks,
                      std::uint64_t seed);

  /// Case 1: a queryrelevance or status from `peer`, another leader of this task.
  void met_leader(int peer, std::int64_t now);
  /// Cases 2-5: `step` from `peer`.
  void receive(int peer, protocol::demotion_step step, std::int64_t now, actions& out);
  /// Sends what is due and ends negotiations past the merge timeout.
  void tick(std::int64_t now, actions& out);
  /// Forgets every negotiation (the leader stopped leading).
  void reset() { peers_.clear(); }

  /// Whether a negotiation with anyone is under way.
  bool negotiating() const noexcept { return !peers_.empty(); }

 private:
  struct peer_state {
    std::optional<std::int64_t> send_at;
    bool sent = false;
    std::int64_t since = 0;
  };
  bool sent_to_anyone() const;
  std::int64_t later(std::int64_t now);

  std::int64_t merge_timeout_ticks_;
  std::int64_t backoff_max_ticks_;
  world::rng rng_;
  std::map<int, peer_state> peers_;
};

}  // namespace argus::controller
