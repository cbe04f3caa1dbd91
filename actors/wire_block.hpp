#pragma once

// A vector of plain records as it crosses to another process: one block of bytes. CAF 0.17
// writes a vector field by field, each through a virtual call that returns an error object;
// the large station's 10,000 walkers' moved states (eight words each) cost that 80,000 times
// a side, on every tick's critical path. Inspectors name such a field `as_block(x.field)`.
//
// The bytes are the records' own, so both ends must lay them out alike: the same Argus build
// (the coordinator and its workers check their versions) on little-endian machines.

#include <bit>
#include <cstddef>
#include <cstring>
#include <iterator>
#include <type_traits>
#include <vector>

#include "caf/binary_deserializer.hpp"
#include "caf/deserializer.hpp"
#include "caf/error.hpp"
#include "caf/sec.hpp"
#include "caf/serializer.hpp"

namespace argus::actors {

static_assert(std::endian::native == std::endian::little,
              "records cross as their bytes: big-endian machines are not supported");

template <class T>
struct block_of {
  static_assert(std::is_trivially_copyable_v<T> && std::has_unique_object_representations_v<T>,
                "a block crosses as its bytes: no padding, no pointers");
  std::vector<T>& items;
};

template <class T>
block_of<T> as_block(std::vector<T>& items) {
  return {items};
}

namespace detail {

// Reads `count` records. A binary source (what the middleman reads messages with, seen here as
// a plain deserializer) says how many bytes it has left, so a count it cannot hold fails
// before anything is allocated; any other source is read record by record.
template <class T>
caf::error read_block(caf::deserializer& source, std::size_t count, std::vector<T>& out) {
  if (auto* binary = dynamic_cast<caf::binary_deserializer*>(&source)) {
    if (count > binary->remaining() / sizeof(T)) return caf::make_error(caf::sec::end_of_stream);
    out.resize(count);
    return count > 0 ? binary->apply_raw(count * sizeof(T), out.data()) : caf::error{};
  }
  out.clear();
  for (std::size_t i = 0; i < count; ++i) {
    T item;
    if (auto err = source.apply_raw(sizeof(T), &item)) return err;
    out.push_back(item);
  }
  return caf::error{};
}

}  // namespace detail

/// The records that follow a block of heads, handed out in runs, in order: each head says how
/// many are its. A run longer than what is left is refused, and `all_taken` says whether any
/// was left over: counts that do not add up are a message that was not made by Argus.
template <class Items>
class runs_of {
 public:
  explicit runs_of(Items& items) : items_(items) {}
  /// Moves the next `count` items into `out`; false (and nothing moved) when fewer are left.
  template <class Out>
  bool take(std::size_t count, Out& out) {
    if (count > items_.size() - next_) return false;
    const auto from = items_.begin() + static_cast<std::ptrdiff_t>(next_);
    out.assign(std::make_move_iterator(from),
               std::make_move_iterator(from + static_cast<std::ptrdiff_t>(count)));
    next_ += count;
    return true;
  }
  bool all_taken() const { return next_ == items_.size(); }

 private:
  Items& items_;
  std::size_t next_ = 0;
};

template <class Inspector, class T>
typename Inspector::result_type inspect(Inspector& f, block_of<T>& x) {
  if constexpr (std::is_base_of_v<caf::serializer, Inspector>) {
    auto count = x.items.size();
    if (auto err = f.begin_sequence(count)) return err;
    if (count > 0)
      if (auto err = f.apply_raw(count * sizeof(T), x.items.data())) return err;
    return f.end_sequence();
  } else if constexpr (std::is_base_of_v<caf::deserializer, Inspector>) {
    std::size_t count = 0;
    if (auto err = f.begin_sequence(count)) return err;
    if (auto err = detail::read_block(f, count, x.items)) return err;
    return f.end_sequence();
  } else {
    return f(x.items);  // not a wire: printing, say
  }
}

}  // namespace argus::actors
