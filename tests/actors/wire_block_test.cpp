// A delta's moved states cross as one block of bytes (actors/wire_block.hpp): bit for bit, in
// one piece, and a count the bytes cannot hold fails before anything is allocated.

#include "actors/wire_block.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "actors/snapshot_delta.hpp"
#include "caf/binary_deserializer.hpp"
#include "caf/binary_serializer.hpp"
#include "caf/stream_deserializer.hpp"
#include "caf/stream_serializer.hpp"
#include "caf/streambuf.hpp"

namespace argus::actors::testing {
namespace {

std::vector<moved_state> some_moves(std::size_t count) {
  std::vector<moved_state> out(count);
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t k = 0; k < 8; ++k) out[i].bits[k] = i * 0x9e3779b97f4a7c15ULL + k;
  // A negative zero and a NaN with a payload: what CAF's own packing of doubles would not keep.
  out[0].bits[0] = std::bit_cast<std::uint64_t>(-0.0);
  out[0].bits[1] = 0x7ff8000000000123ULL;
  return out;
}

TEST(wire_block, moved_states_cross_bit_for_bit_as_one_block) {
  auto moves = some_moves(1000);
  std::vector<char> bytes;
  caf::binary_serializer sink{nullptr, bytes};
  auto out = as_block(moves);
  ASSERT_FALSE(sink(out));
  // The count (1,000 takes two bytes) and the records' bytes, nothing per record or field.
  EXPECT_EQ(bytes.size(), 2 + 1000 * sizeof(moved_state));
  // The records' own bytes: CAF's field by field writes each word big-endian instead.
  EXPECT_EQ(std::memcmp(bytes.data() + 2, moves.data(), 1000 * sizeof(moved_state)), 0);
  std::vector<moved_state> back;
  caf::binary_deserializer source{nullptr, bytes};
  auto in = as_block(back);
  ASSERT_FALSE(source(in));
  EXPECT_EQ(back, moves);
  EXPECT_EQ(source.remaining(), 0u);
}

TEST(wire_block, a_count_the_bytes_cannot_hold_fails_without_allocating_it) {
  std::vector<char> bytes;
  caf::binary_serializer sink{nullptr, bytes};
  std::size_t claimed = std::size_t{1} << 30;  // 64 GiB of records (CAF counts in 32 bits)
  ASSERT_FALSE(sink.begin_sequence(claimed));
  auto one = some_moves(1);
  ASSERT_FALSE(sink.apply_raw(sizeof(moved_state), one.data()));
  std::vector<moved_state> back;
  caf::binary_deserializer source{nullptr, bytes};
  auto in = as_block(back);
  EXPECT_TRUE(source(in));
  EXPECT_EQ(back.capacity(), 0u);
}

TEST(wire_block, a_source_that_is_not_binary_reads_the_same_records) {
  auto moves = some_moves(37);
  std::vector<char> bytes;
  {
    caf::stream_serializer<caf::vectorbuf> sink{nullptr, bytes};
    auto out = as_block(moves);
    ASSERT_FALSE(sink(out));
  }
  std::vector<moved_state> back;
  caf::stream_deserializer<caf::charbuf> source{nullptr, bytes.data(), bytes.size()};
  auto in = as_block(back);
  ASSERT_FALSE(source(in));
  EXPECT_EQ(back, moves);
}

TEST(wire_block, a_snapshot_delta_keeps_its_moves_through_a_serialisation) {
  snapshot_delta delta;
  delta.tick = 7;
  delta.changes = {1, 1, 0};
  delta.moved = some_moves(2);
  auto bytes = serialize(delta);
  // The delta's moves are in it as their own bytes, in one piece.
  const auto* raw = reinterpret_cast<const char*>(delta.moved.data());
  EXPECT_NE(std::search(bytes.bytes.begin(), bytes.bytes.end(), raw,
                        raw + delta.moved.size() * sizeof(moved_state)),
            bytes.bytes.end());
  const auto back = deserialize(bytes);
  EXPECT_EQ(back.tick, 7u);
  EXPECT_EQ(back.changes, delta.changes);
  EXPECT_EQ(back.moved, delta.moved);
}

}  // namespace
}  // namespace argus::actors::testing
