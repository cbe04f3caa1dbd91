// Partitions: the union of the strips' results equals the single-partition result bit for
// bit, and hand-over neither loses nor duplicates anyone.
//
//   x: 0        50        100       150       200
//      | strip 0 | strip 1 | strip 2 | strip 3 |
#include <gtest/gtest.h>

#include <set>

#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::world {
namespace {

std::shared_ptr<const station> penn() {
  static const auto shared = station::load(builtin_layout_path());
  return shared;
}

crowd_settings settings_with(unsigned partitions) {
  crowd_settings settings;
  settings.run_seed = 11;
  settings.population = 300;
  settings.spawn_rate_per_min = 120;
  settings.partitions = partitions;
  return settings;
}

TEST(partition, one_and_four_partitions_give_identical_results) {
  crowd one(penn(), settings_with(1));
  crowd four(penn(), settings_with(4));
  std::size_t hand_overs = 0;
  for (int k = 0; k < 15 * 90; ++k) {
    one.step();
    four.step();
    hand_overs += four.last_hand_overs();
    const auto a = one.current()->pedestrians();
    const auto b = four.current()->pedestrians();
    ASSERT_EQ(a.size(), b.size()) << "tick " << k;
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a[i].id, b[i].id);
      // Exact comparison on purpose: same snapshot, same operations, same bits.
      ASSERT_EQ(a[i].position.x(), b[i].position.x()) << "id " << a[i].id << " tick " << k;
      ASSERT_EQ(a[i].position.y(), b[i].position.y()) << "id " << a[i].id << " tick " << k;
      ASSERT_EQ(a[i].velocity, b[i].velocity);
      ASSERT_EQ(a[i].doing, b[i].doing);
    }
    ASSERT_EQ(one.current()->events().size(), four.current()->events().size());
    for (std::size_t i = 0; i < one.current()->events().size(); ++i) {
      ASSERT_EQ(one.current()->events()[i], four.current()->events()[i]);
    }
  }
  // The run must actually exercise hand-over.
  EXPECT_GT(hand_overs, 50u);
}

TEST(partition, hand_over_loses_and_duplicates_no_one) {
  crowd four(penn(), settings_with(4));
  for (int k = 0; k < 15 * 60; ++k) {
    four.step();
    std::set<int> owned;
    std::size_t count = 0;
    for (std::size_t i = 0; i < four.owned().size(); ++i) {
      for (const auto& p : four.owned()[i]) {
        ++count;
        owned.insert(p.state.id);
        // Everyone is owned by the strip that contains them.
        ASSERT_TRUE(four.bounds()[i].contains(p.state.position)) << p.state.id;
      }
    }
    ASSERT_EQ(count, owned.size()) << "duplicate at tick " << k;
    std::set<int> in_snapshot;
    for (const auto& p : four.current()->pedestrians()) in_snapshot.insert(p.id);
    ASSERT_EQ(owned, in_snapshot) << "lost or extra at tick " << k;
  }
}

TEST(partition, partition_step_hands_over_who_crossed) {
  const auto& where = *penn();
  crowd world(penn(), settings_with(1));
  const auto strips = vertical_strips(where, 2);
  ASSERT_EQ(strips.size(), 2u);
  EXPECT_EQ(strips[0].max_x_m, 100.0);
  // Step strip 0's pedestrians until someone crosses x = 100.
  const auto& everyone = world.owned()[0];
  std::vector<pedestrian> left_strip;
  for (const auto& p : everyone) {
    if (strips[0].contains(p.state.position)) left_strip.push_back(p);
  }
  const auto result = partition_step(where, *world.current(), left_strip, strips[0], {});
  EXPECT_EQ(result.pedestrians.size() + result.handed_over.size(), left_strip.size());
  for (const auto& p : result.pedestrians) EXPECT_TRUE(strips[0].contains(p.state.position));
  for (const auto& p : result.handed_over) EXPECT_FALSE(strips[0].contains(p.state.position));
  EXPECT_EQ(owner_of(strips, vec2{150.0, 50.0}), 1u);
  EXPECT_EQ(owner_of(strips, vec2{-5.0, 50.0}), 0u);
}

}  // namespace
}  // namespace argus::world
