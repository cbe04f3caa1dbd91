#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "fmt/format.h"

namespace argus::protocol {

/// The type of a network message as the paper names them ("queryrelevance", "relevance",
/// "join", "status", "demote", ..., and "hello" for neighbour discovery): a name, carried as a
/// two-byte index into a process-wide table of the names seen so far.
///
/// Every message carries its kind, and the link layer moves tens of thousands of messages per
/// tick; a `std::string` made each message 96 bytes, this makes it 64, one cache line
/// (bench/RESULTS.md, "Turn order"). Which index a name gets depends on which thread saw it
/// first, so nothing may depend on the index but equality: whatever is ordered or printed
/// goes by name.
class message_kind {
 public:
  /// The empty kind.
  message_kind() = default;
  /// The kind named `name`, added to the table on first use. At most `max_kinds` names.
  message_kind(std::string_view name);  // NOLINT: a kind is its name
  message_kind(const std::string& name) : message_kind(std::string_view{name}) {}
  message_kind(const char* name) : message_kind(std::string_view{name}) {}

  /// Its name; valid for the life of the process.
  const std::string& name() const noexcept;

  bool empty() const noexcept { return index_ == 0; }

  friend bool operator==(message_kind a, message_kind b) noexcept { return a.index_ == b.index_; }
  friend bool operator==(message_kind a, std::string_view b) { return a.name() == b; }
  friend bool operator==(message_kind a, const char* b) { return a.name() == b; }

  /// How many distinct names one process may use.
  static constexpr std::size_t max_kinds = 4096;

 private:
  std::uint16_t index_ = 0;
};

/// Saved and loaded by name: an index means nothing in another process.
template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, message_kind& x) {
  std::string name = x.name();
  if constexpr (Inspector::reads_state) {
    return f(name);
  } else {
    auto result = f(name);
    x = message_kind{name};
    return result;
  }
}

}  // namespace argus::protocol

template <>
struct fmt::formatter<argus::protocol::message_kind> : fmt::formatter<std::string_view> {
  template <class FormatContext>
  auto format(const argus::protocol::message_kind& kind, FormatContext& ctx) const {
    return fmt::formatter<std::string_view>::format(kind.name(), ctx);
  }
};
