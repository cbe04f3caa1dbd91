#include "protocol/message_kind.hpp"

#include <array>
#include <atomic>
#include <deque>
#include <mutex>
#include <shared_mutex>
#include <stdexcept>
#include <unordered_map>

namespace argus::protocol {
namespace {

// Append-only. A name, once in, never moves (a deque keeps its elements in place), so name()
// reads it through an atomic pointer without a lock; only lookups by name take one.
class kind_table {
 public:
  kind_table() { add(""); }

  std::uint16_t index_of(std::string_view name) {
    {
      std::shared_lock guard(lock_);
      if (auto it = by_name_.find(name); it != by_name_.end()) return it->second;
    }
    std::unique_lock guard(lock_);
    if (auto it = by_name_.find(name); it != by_name_.end()) return it->second;
    return add(name);
  }

  const std::string& name(std::uint16_t index) const noexcept {
    return *names_by_index_[index].load(std::memory_order_acquire);
  }

 private:
  std::uint16_t add(std::string_view name) {
    if (names_.size() >= message_kind::max_kinds)
      throw std::length_error("more than " + std::to_string(message_kind::max_kinds) +
                              " distinct network message kinds; the next was '" +
                              std::string{name} + "'");
    auto index = static_cast<std::uint16_t>(names_.size());
    const auto& stored = names_.emplace_back(name);
    by_name_.emplace(stored, index);
    names_by_index_[index].store(&stored, std::memory_order_release);
    return index;
  }

  std::shared_mutex lock_;
  std::deque<std::string> names_;
  std::unordered_map<std::string_view, std::uint16_t> by_name_;
  std::array<std::atomic<const std::string*>, message_kind::max_kinds> names_by_index_{};
};

kind_table& table() {
  static kind_table instance;
  return instance;
}

}  // namespace

message_kind::message_kind(std::string_view name)
    : index_(name.empty() ? std::uint16_t{0} : table().index_of(name)) {}

const std::string& message_kind::name() const noexcept {
  return table().name(index_);
}

}  // namespace argus::protocol
