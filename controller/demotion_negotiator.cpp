#include "controller/demotion_negotiator.hpp"

#include <algorithm>

namespace argus::controller {

using protocol::demotion_step;

demotion_negotiator::demotion_negotiator(std::int64_t merge_timeout_ticks,
                                         std::int64_t backoff_max_ticks, std::uint64_t seed)
    : merge_timeout_ticks_(merge_timeout_ticks),
      backoff_max_ticks_(std::max<std::int64_t>(0, backoff_max_ticks)),
      rng_(seed) {
  // nop
}

bool demotion_negotiator::sent_to_anyone() const {
  return std::any_of(peers_.begin(), peers_.end(), [](const auto& p) { return p.second.sent; });
}

std::int64_t demotion_negotiator::later(std::int64_t now) {
  return now + rng_.below(static_cast<std::uint32_t>(backoff_max_ticks_ + 1));
}

void demotion_negotiator::met_leader(int peer, std::int64_t now) {
  if (negotiating()) return;  // Case 1: only when not negotiating with another node
  peers_[peer] = peer_state{later(now), false, now};
}

void demotion_negotiator::receive(int peer, demotion_step step, std::int64_t now, actions& out) {
  switch (step) {
    case demotion_step::demote: {
      auto it = peers_.find(peer);
      if (!sent_to_anyone()) {  // Case 2.1
        out.sends.emplace_back(peer, demotion_step::ack);
        out.demoted_to = peer;
        peers_.clear();
      } else if (it != peers_.end() && it->second.sent) {  // Case 2.2: a collision
        out.sends.emplace_back(peer, demotion_step::retry);
        it->second = peer_state{later(now), false, now};
      } else {  // Case 2.3
        out.sends.emplace_back(peer, demotion_step::nack);
      }
      break;
    }
    case demotion_step::nack:  // Case 3
      peers_.erase(peer);
      break;
    case demotion_step::ack:  // Case 4
      out.absorbed.push_back(peer);
      peers_.erase(peer);
      break;
    case demotion_step::retry:  // Case 5
      peers_[peer] = peer_state{later(now), false, now};
      break;
  }
}

void demotion_negotiator::tick(std::int64_t now, actions& out) {
  for (auto it = peers_.begin(); it != peers_.end();) {
    auto& p = it->second;
    if (p.send_at && *p.send_at <= now) {
      out.sends.emplace_back(it->first, demotion_step::demote);
      p.send_at.reset();
      p.sent = true;
      p.since = now;
    }
    if (now - p.since >= merge_timeout_ticks_) {
      it = peers_.erase(it);
    } else {
      ++it;
    }
  }
}

}  // namespace argus::controller
