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
#include "actors/tick_ack.hpp"
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

// A worker's answer to the clock: 512 acknowledgements, most of them carrying nothing.
std::vector<tick_ack> an_answer() {
  std::vector<tick_ack> acks(512);
  for (std::size_t i = 0; i < acks.size(); ++i) {
    acks[i].participant = 1000 + i;
    acks[i].tick = 77;
    acks[i].next_wakeup = i % 5 == 0 ? 80 : no_wakeup;
  }
  acks[3].woken = {4, 9};
  acks[3].relayed = {9};
  acks[3].events.push_back({77, 3, 1003, 0, "camera/4", "handoff", "\"to\":9"});
  acks[3].events.push_back({77, 3, 1003, 1, "camera/4", "joined", ""});
  acks[300].relayed = {1, 1, 2};
  acks[511].stop_run = "the strategy raised";
  acks[511].events.push_back({77, 3, 1511, 0, "camera/512", "crash", ""});
  return acks;
}

TEST(wire_block, a_sub_clocks_answer_crosses_whole_and_its_heads_as_one_block) {
  auto sent = an_answer();
  std::vector<char> bytes;
  caf::binary_serializer sink{nullptr, bytes};
  ASSERT_FALSE(sink(sent));
  std::vector<tick_ack> back;
  caf::binary_deserializer source{nullptr, bytes};
  ASSERT_FALSE(source(back));
  EXPECT_EQ(source.remaining(), 0u);
  EXPECT_EQ(back, sent);
  // Acknowledgements that carry nothing: their heads' block (a two-byte count, then the heads'
  // own bytes, little-endian, where CAF would write each field big-endian) and four empty tails.
  std::vector<tick_ack> bare(512);
  bare[0].participant = 0x0102030405060708ULL;
  std::vector<char> bare_bytes;
  caf::binary_serializer bare_sink{nullptr, bare_bytes};
  ASSERT_FALSE(bare_sink(bare));
  EXPECT_EQ(bare_bytes.size(), 2 + 512 * sizeof(ack_head) + 4);
  EXPECT_EQ(std::memcmp(bare_bytes.data() + 2, &bare[0].participant, 8), 0);
}

TEST(wire_block, an_answer_whose_counts_do_not_add_up_is_refused) {
  auto sent = an_answer();
  std::vector<char> bytes;
  caf::binary_serializer sink{nullptr, bytes};
  ASSERT_FALSE(sink(sent));
  // The first head's woken count, one more than its woken follow: the heads are the block
  // after the count (two bytes for 512), and the count lies 24 bytes into each head.
  std::uint32_t woken = 0;
  std::memcpy(&woken, bytes.data() + 2 + 24, sizeof woken);
  ASSERT_EQ(woken, 0u);
  woken = 7;
  std::memcpy(bytes.data() + 2 + 24, &woken, sizeof woken);
  std::vector<tick_ack> back;
  caf::binary_deserializer source{nullptr, bytes};
  EXPECT_TRUE(source(back));
}

TEST(wire_block, a_batch_of_ticks_crosses_as_its_bytes) {
  std::vector<batched_tick> due;
  for (std::uint32_t i = 0; i < 300; ++i) due.push_back({5000 + i, i % 3, 0});
  std::vector<char> bytes;
  caf::binary_serializer sink{nullptr, bytes};
  ASSERT_FALSE(sink(due));
  EXPECT_EQ(bytes.size(), 2 + 300 * sizeof(batched_tick));
  std::vector<batched_tick> back;
  caf::binary_deserializer source{nullptr, bytes};
  ASSERT_FALSE(source(back));
  ASSERT_EQ(back.size(), due.size());
  for (std::size_t i = 0; i < due.size(); ++i) {
    EXPECT_EQ(back[i].participant, due[i].participant);
    EXPECT_EQ(back[i].relayed, due[i].relayed);
  }
}

}  // namespace
}  // namespace argus::actors::testing
