#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace argus::protocol {

/// Fates of the messages one link (or the whole network) carried. Every transmission the link
/// accepted, and every duplicate it made, ends in exactly one of the other four counts:
///   sent + duplicated == delivered + lost + dropped + in_flight.
struct message_counts {
  std::uint64_t sent = 0;
  std::uint64_t duplicated = 0;
  std::uint64_t delivered = 0;
  /// Lost on the link: random loss, loss bursts, or a cut link.
  std::uint64_t lost = 0;
  /// Reached a node that was down.
  std::uint64_t dropped = 0;
  std::uint64_t in_flight = 0;

  /// True when the invariant above holds.
  bool balanced() const noexcept {
    return sent + duplicated == delivered + lost + dropped + in_flight;
  }

  message_counts& operator+=(const message_counts& o) noexcept {
    sent += o.sent;
    duplicated += o.duplicated;
    delivered += o.delivered;
    lost += o.lost;
    dropped += o.dropped;
    in_flight += o.in_flight;
    return *this;
  }

  friend bool operator==(const message_counts&, const message_counts&) = default;
};

/// Counts per message kind ("hello", "queryrelevance", ...).
using accounting_by_kind = std::map<std::string, message_counts>;

/// Adds `b` into `a`, kind by kind.
inline void merge(accounting_by_kind& a, const accounting_by_kind& b) {
  for (const auto& [kind, counts] : b) a[kind] += counts;
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, message_counts& x) {
  return f(x.sent, x.duplicated, x.delivered, x.lost, x.dropped, x.in_flight);
}

}  // namespace argus::protocol
