#pragma once

#include <cstdint>
#include <string>

#include "protocol/message_kind.hpp"

namespace argus::protocol {

/// Destination of a message to every node within the hop limit.
inline constexpr int broadcast = -1;

/// One message between camera nodes as the network carries it (Sections I-B, IV; Table 2).
/// `id` is unique per origin (origin << 32 | per-origin counter) so that flooding can suppress
/// duplicates; `hops` counts the links crossed so far.
///
/// 64 bytes, one cache line: the link layer moves every message several times per hop.
struct net_message {
  std::uint64_t id = 0;
  /// The id of the request this message answers; 0 when it answers none.
  std::uint64_t reply_to = 0;
  int origin = 0;
  int destination = broadcast;
  message_kind kind;
  std::uint8_t hops = 0;
  std::uint8_t max_hops = 3;
  /// The protocol payload, serialised by protocol/.
  std::string body;

  friend bool operator==(const net_message&, const net_message&) = default;
};

/// Makes the id of the `seq`-th message sent by node `origin`.
constexpr std::uint64_t make_message_id(int origin, std::uint32_t seq) noexcept {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(origin)) << 32) | seq;
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, net_message& x) {
  return f(x.id, x.reply_to, x.origin, x.destination, x.kind, x.hops, x.max_hops, x.body);
}

}  // namespace argus::protocol

static_assert(sizeof(argus::protocol::net_message) == 64, "a network message is one cache line");
