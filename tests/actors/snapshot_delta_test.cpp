// A snapshot crosses to a worker as a delta from the one before (actors/snapshot_delta.hpp):
// through CAF's serializer, tick after tick, the worker must rebuild the coordinator's world
// bit for bit, and refuse a delta that was not made from the snapshot it holds.

#include "actors/snapshot_delta.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "caf/binary_deserializer.hpp"
#include "caf/binary_serializer.hpp"
#include "config/scenario_loader.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::actors::testing {
namespace {

// The states one partition's subset describes.
std::vector<world::pedestrian_state> apply_one(const world::snapshot& before, subset_delta delta) {
  std::vector<subset_delta> one;
  one.push_back(std::move(delta));
  return std::move(apply_subsets(before, std::move(one)).front());
}

std::uint64_t bits_of(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// Equal as values, and as bits where a sign of zero would show (the heading drawn from the
// facing).
void expect_same_world(const world::snapshot& got, const world::snapshot& want) {
  ASSERT_EQ(got.tick(), want.tick());
  EXPECT_EQ(got.time(), want.time());
  ASSERT_EQ(got.pedestrians().size(), want.pedestrians().size()) << "tick " << want.tick();
  for (std::size_t i = 0; i < want.pedestrians().size(); ++i) {
    const auto& g = got.pedestrians()[i];
    const auto& w = want.pedestrians()[i];
    ASSERT_TRUE(g == w) << "tick " << want.tick() << ", pedestrian " << w.id;
    ASSERT_EQ(bits_of(g.heading_rad()), bits_of(w.heading_rad())) << "pedestrian " << w.id;
    ASSERT_EQ(bits_of(g.velocity.x()), bits_of(w.velocity.x())) << "pedestrian " << w.id;
  }
  ASSERT_EQ(got.events().size(), want.events().size());
  for (std::size_t i = 0; i < want.events().size(); ++i)
    EXPECT_TRUE(got.events()[i] == want.events()[i]);
}

config::scenario delta_scenario() {
  const auto scenarios = std::filesystem::path(ARGUS_SOURCE_DIR) / "scenarios";
  return config::load_scenario(scenarios / "replay_faults.yaml");
}

// What a worker does with a delta: it arrives as bytes.
std::shared_ptr<const world::snapshot> received(const world::station& where,
                                                const world::snapshot* last, snapshot_delta delta) {
  return apply_delta(where, last, deserialize(serialize(delta)));
}

world::pedestrian_state walker_at(int id, double x) {
  world::pedestrian_state p;
  p.id = id;
  p.position = {x, 5.0};
  p.velocity = {1.0, 0.0};
  p.facing = {1.0, 0.0};
  return p;
}

TEST(snapshot_delta, a_worker_rebuilds_every_tick_of_a_crowd_bit_for_bit) {
  const auto s = delta_scenario();
  auto station = world::station::load(world::layout_path(s));
  world::crowd crowd(station, world::crowd_settings::from(s));
  auto sent = crowd.current();
  auto held = received(*station, nullptr, delta_between(nullptr, *sent));
  expect_same_world(*held, *sent);
  std::size_t arrived = 0;
  std::size_t gone = 0;
  std::size_t moved = 0;
  std::size_t whole = 0;
  std::size_t people = 0;
  for (int tick = 0; tick < 900; ++tick) {
    crowd.step();
    auto now = crowd.current();
    auto delta = delta_between(sent.get(), *now);
    for (auto c : delta.changes)
      if (static_cast<pedestrian_change>(c) == pedestrian_change::arrived) ++arrived;
    for (auto g : delta.gone) gone += g;
    moved += delta.moved.size();
    whole += delta.whole.size();
    people += now->pedestrians().size();
    held = received(*station, held.get(), std::move(delta));
    expect_same_world(*held, *now);
    if (HasFatalFailure()) return;
    sent = now;
  }
  // The run saw people come and go, and most of the crowd crossed as moves or not at all.
  EXPECT_GT(arrived, 0u);
  EXPECT_GT(gone, 0u);
  EXPECT_GT(moved, people / 4);
  EXPECT_LT(whole, people / 10);
}

TEST(snapshot_delta, a_sign_of_zero_crosses) {
  auto station = world::station::load(world::layout_path(delta_scenario()));
  auto stopping = walker_at(7, 3.0);
  world::snapshot before(*station, 1, std::chrono::duration<double>{0.1}, {stopping});
  stopping.velocity = {-0.0, 0.0};
  stopping.facing = {-0.0, 0.0};
  world::snapshot after(*station, 2, std::chrono::duration<double>{0.2}, {stopping});
  auto delta = delta_between(&before, after);
  ASSERT_EQ(delta.changes.size(), 1u);
  EXPECT_EQ(static_cast<pedestrian_change>(delta.changes[0]), pedestrian_change::moved);
  auto held = received(*station, &before, std::move(delta));
  EXPECT_TRUE(std::signbit(held->pedestrians()[0].velocity.x()));
  expect_same_world(*held, after);
}

TEST(snapshot_delta, leaving_arriving_and_changing_in_one_tick) {
  auto station = world::station::load(world::layout_path(delta_scenario()));
  world::snapshot before(
      *station, 1, std::chrono::duration<double>{0.1},
      {walker_at(1, 1.0), walker_at(2, 2.0), walker_at(3, 3.0), walker_at(4, 4.0)});
  auto seated = walker_at(3, 3.0);
  seated.doing = world::activity::sitting;
  seated.seat = 5;
  world::snapshot after(
      *station, 2, std::chrono::duration<double>{0.2},
      {walker_at(1, 1.0), walker_at(2, 2.5), seated, walker_at(9, 9.0)},
      {world::event{2, 9, world::event_kind::spawned, world::goal_kind::go_to_platform, 0}});
  auto delta = delta_between(&before, after);
  using c = pedestrian_change;
  const std::vector<std::uint8_t> changes = {
      static_cast<std::uint8_t>(c::kept), static_cast<std::uint8_t>(c::moved),
      static_cast<std::uint8_t>(c::changed), static_cast<std::uint8_t>(c::arrived)};
  EXPECT_EQ(delta.changes, changes);
  EXPECT_EQ(delta.gone, (std::vector<std::uint8_t>{0, 0, 0, 1}));
  EXPECT_EQ(delta.moved.size(), 1u);
  EXPECT_EQ(delta.whole.size(), 2u);
  expect_same_world(*received(*station, &before, std::move(delta)), after);
}

TEST(snapshot_delta, a_delta_for_another_snapshot_is_refused) {
  auto station = world::station::load(world::layout_path(delta_scenario()));
  world::snapshot before(*station, 1, std::chrono::duration<double>{0.1},
                         {walker_at(1, 1.0), walker_at(2, 2.0)});
  world::snapshot after(*station, 2, std::chrono::duration<double>{0.2},
                        {walker_at(1, 1.5), walker_at(2, 2.5)});
  world::snapshot other(*station, 1, std::chrono::duration<double>{0.1},
                        {walker_at(1, 1.0), walker_at(5, 2.0)});
  world::snapshot fewer(*station, 1, std::chrono::duration<double>{0.1}, {walker_at(1, 1.0)});
  // Another crowd of the same size: pedestrian 2 changed in the place of 5.
  auto changed = walker_at(2, 2.0);
  changed.seat = 3;
  world::snapshot seated(*station, 2, std::chrono::duration<double>{0.2},
                         {walker_at(1, 1.5), changed});
  EXPECT_THROW(received(*station, &other, delta_between(&before, seated)), std::invalid_argument);
  // Another size: found at once.
  try {
    received(*station, &fewer, delta_between(&before, after));
    FAIL() << "a delta for two pedestrians applied to one";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("it is for 2 pedestrians"), std::string::npos) << e.what();
  }
  // No snapshot held yet (a worker that missed the first).
  EXPECT_THROW(received(*station, nullptr, delta_between(&before, after)), std::invalid_argument);
  // Bytes that are not a delta.
  EXPECT_THROW(deserialize(serialized_delta{{'n', 'o', 't'}}), std::invalid_argument);
}

world::pedestrian whole(const world::pedestrian_state& state) {
  world::pedestrian p;
  p.state = state;
  return p;
}

// A crowd partition on a worker reports the pedestrians it kept as changes to the snapshot it
// stepped from (wire_partition.hpp): some of its pedestrians, not all; through CAF's serializer.
TEST(snapshot_delta, a_partitions_kept_pedestrians_cross_as_changes) {
  auto station = world::station::load(world::layout_path(delta_scenario()));
  world::snapshot before(
      *station, 1, std::chrono::duration<double>{0.1},
      {walker_at(1, 1.0), walker_at(2, 2.0), walker_at(3, 3.0), walker_at(4, 4.0)});
  auto stopped = walker_at(2, 2.5);
  stopped.velocity = {-0.0, 0.0};
  auto seated = walker_at(4, 4.0);
  seated.doing = world::activity::sitting;
  const std::vector<world::pedestrian> kept{whole(walker_at(1, 1.0)), whole(stopped),
                                            whole(seated)};
  auto delta = subset_between(before, kept);
  using c = pedestrian_change;
  EXPECT_EQ(delta.changes,
            (std::vector<std::uint8_t>{static_cast<std::uint8_t>(c::kept),
                                       static_cast<std::uint8_t>(c::moved), subset_delta::absent,
                                       static_cast<std::uint8_t>(c::changed)}));
  std::vector<char> bytes;
  caf::binary_serializer sink{nullptr, bytes};
  ASSERT_FALSE(sink(delta));
  subset_delta crossed;
  caf::binary_deserializer source{nullptr, bytes};
  ASSERT_FALSE(source(crossed));
  const auto states = apply_one(before, crossed);
  ASSERT_EQ(states.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_TRUE(states[k] == kept[k].state) << k;
  EXPECT_TRUE(std::signbit(states[1].velocity.x()));
  // Applied to another snapshot, or made from one that lacks a pedestrian: refused.
  world::snapshot fewer(*station, 1, std::chrono::duration<double>{0.1}, {walker_at(1, 1.0)});
  EXPECT_THROW(apply_one(fewer, crossed), std::invalid_argument);
  EXPECT_THROW(subset_between(fewer, kept), std::invalid_argument);
}

// The coordinator reads every worker partition's report in one pass over the snapshot they
// stepped from: each subset comes back as it would alone, whoever else holds the pedestrians
// around its own.
TEST(snapshot_delta, several_partitions_subsets_are_read_together_as_each_alone) {
  auto station = world::station::load(world::layout_path(delta_scenario()));
  std::vector<world::pedestrian_state> everyone;
  for (int id = 1; id <= 30; ++id) everyone.push_back(walker_at(id, 0.5 * id));
  world::snapshot before(*station, 1, std::chrono::duration<double>{0.1}, everyone);
  // Three partitions that hold every third pedestrian, interleaved in id order; the third
  // holds none from 20 on. Some moved, some changed, some as they were.
  std::vector<std::vector<world::pedestrian>> held(3);
  for (const auto& state : everyone) {
    const auto part = static_cast<std::size_t>(state.id % 3);
    if (part == 2 && state.id >= 20) continue;
    auto now = state;
    if (state.id % 4 == 0) now.position.x() += 0.1;
    if (state.id % 7 == 0) now.goal_serial += 1;
    held[part].push_back(whole(now));
  }
  std::vector<subset_delta> deltas;
  for (const auto& kept : held) deltas.push_back(subset_between(before, kept));
  const auto together = apply_subsets(before, deltas);
  ASSERT_EQ(together.size(), 3u);
  for (std::size_t part = 0; part < 3; ++part) {
    const auto alone = apply_one(before, deltas[part]);
    ASSERT_EQ(together[part].size(), held[part].size()) << part;
    ASSERT_EQ(alone.size(), held[part].size()) << part;
    for (std::size_t k = 0; k < held[part].size(); ++k) {
      EXPECT_TRUE(together[part][k] == held[part][k].state) << part << " " << k;
      EXPECT_TRUE(alone[k] == held[part][k].state) << part << " " << k;
    }
  }
  // One subset that does not fit refuses them all.
  deltas[1].changes.pop_back();
  EXPECT_THROW(apply_subsets(before, deltas), std::invalid_argument);
}

}  // namespace
}  // namespace argus::actors::testing
