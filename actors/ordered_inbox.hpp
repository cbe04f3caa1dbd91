#pragma once

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace argus::actors {

/// Where and when a message between participants was sent; orders mail canonically.
struct mail_stamp {
  std::int64_t tick = 0;
  std::uint8_t phase = 0;
  std::uint64_t sender = 0;
  /// Per-sender counter: the order in which the sender sent.
  std::uint64_t seq = 0;

  friend auto operator<=>(const mail_stamp&, const mail_stamp&) = default;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, mail_stamp& x) {
  return f(x.tick, x.phase, x.sender, x.seq);
}

/// Buffers mail between participants and releases it in a canonical order, so a run does not
/// depend on the order in which different senders' messages reached the mailbox.
///
/// Mail stamped in the receiver's own (tick, phase) or later is held back: a peer of the same
/// phase may or may not have sent it yet when the receiver runs, so reading it now would make
/// the run depend on thread timing. It is read at the receiver's next turn instead.
template <class Payload>
class ordered_inbox {
 public:
  /// Stores one message.
  void put(mail_stamp stamp, Payload payload) { mail_.emplace_back(stamp, std::move(payload)); }

  /// Removes and returns, in canonical order, all mail sent before (`tick`, `phase`).
  std::vector<std::pair<mail_stamp, Payload>> take_due(std::int64_t tick, std::uint8_t phase) {
    auto before = [&](const auto& m) {
      return std::tie(m.first.tick, m.first.phase) < std::tie(tick, phase);
    };
    std::vector<std::pair<mail_stamp, Payload>> due;
    if (std::all_of(mail_.begin(), mail_.end(), before)) {
      // The common case: everything held is due. Hand over the storage itself.
      due.swap(mail_);
    } else {
      auto due_end = std::partition(mail_.begin(), mail_.end(), before);
      due.assign(std::make_move_iterator(mail_.begin()), std::make_move_iterator(due_end));
      mail_.erase(mail_.begin(), due_end);
    }
    sort_by_stamp(due);
    return due;
  }
  /// Drops every held message whose stamp satisfies `pred`.
  template <class Predicate>
  void discard_if(Predicate pred) {
    mail_.erase(
        std::remove_if(mail_.begin(), mail_.end(), [&](const auto& m) { return pred(m.first); }),
        mail_.end());
  }

  /// Number of messages held.
  std::size_t size() const noexcept { return mail_.size(); }

 private:
  // Sorts by stamp, moving each payload once: payloads can be large (a network message with
  // its strings), stamps are small, and a sort of the pairs themselves moved each payload
  // many times.
  static void sort_by_stamp(std::vector<std::pair<mail_stamp, Payload>>& mail) {
    auto by_stamp = [](const auto& a, const auto& b) { return a.first < b.first; };
    if (std::is_sorted(mail.begin(), mail.end(), by_stamp)) return;
    std::vector<std::pair<mail_stamp, std::size_t>> order;
    order.reserve(mail.size());
    for (std::size_t i = 0; i < mail.size(); ++i) order.emplace_back(mail[i].first, i);
    std::sort(order.begin(), order.end());
    std::vector<std::pair<mail_stamp, Payload>> sorted;
    sorted.reserve(mail.size());
    for (const auto& [stamp, i] : order) sorted.push_back(std::move(mail[i]));
    mail.swap(sorted);
  }

  std::vector<std::pair<mail_stamp, Payload>> mail_;
};

}  // namespace argus::actors
