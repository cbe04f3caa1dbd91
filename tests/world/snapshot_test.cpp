// Snapshots: id order, neighbour index, line ranks by (join tick, id), seat holder by lowest id.
#include "world/snapshot.hpp"

#include <gtest/gtest.h>

#include "world/layout_loader.hpp"
#include "world/rng.hpp"
#include "world/station.hpp"

namespace argus::world {
namespace {

const station& penn() {
  static const auto shared = station::load(builtin_layout_path());
  return *shared;
}

pedestrian_state at(int id, double x, double y) {
  pedestrian_state p;
  p.id = id;
  p.position = {x, y};
  return p;
}

TEST(snapshot, sorts_by_id_and_finds) {
  snapshot s(penn(), 3, std::chrono::duration<double>{0.2},
             {at(5, 100, 50), at(2, 90, 50), at(9, 10, 10)});
  ASSERT_EQ(s.pedestrians().size(), 3u);
  EXPECT_EQ(s.pedestrians()[0].id, 2);
  EXPECT_EQ(s.pedestrians()[2].id, 9);
  ASSERT_NE(s.find(5), nullptr);
  EXPECT_EQ(s.find(5)->position.x(), 100.0);
  EXPECT_EQ(s.find(4), nullptr);
}

TEST(snapshot, neighbours_cover_two_metres) {
  snapshot s(penn(), 1, std::chrono::duration<double>{0.0},
             {at(1, 100, 50), at(2, 101.9, 50), at(3, 100, 51.95), at(4, 104.5, 50)});
  std::vector<int> seen;
  s.for_each_near({100.0, 50.0}, [&](const neighbour& p) { seen.push_back(p.id); });
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3}));
}

// The sifted visit is the plain one with the rejected left out, in the same order: the
// crowd's step sums forces in visiting order, so any reordering would change trajectories.
// 400 people in 6 x 6 m put more than one sifting chunk (128) into a row of cells, and the
// sieve keeps a few of them.
TEST(snapshot, sifted_neighbours_keep_the_order) {
  std::vector<pedestrian_state> crowd;
  rng random(12345);
  for (int id = 1; id <= 400; ++id) {
    auto p = at(id, random.uniform(97.0, 103.0), random.uniform(47.0, 53.0));
    p.velocity = {random.uniform(-1.5, 1.5), random.uniform(-1.5, 1.5)};
    crowd.push_back(p);
  }
  snapshot s(penn(), 1, std::chrono::duration<double>{0.0}, crowd);
  neighbour_sieve sieve;
  sieve.position = {100.0, 50.0};
  sieve.direction = {0.6, 0.8};
  sieve.radius = 0.23;
  sieve.near_gap_m = 0.45;
  sieve.reach_squared = snapshot::neighbour_cell_m * snapshot::neighbour_cell_m;
  sieve.look_m = 2.0;
  sieve.lane_margin_m = 0.3;
  sieve.turning = true;
  std::vector<int> plain;
  std::size_t around = 0;
  s.for_each_near(sieve.position, [&](const neighbour& p) {
    ++around;
    if (sieve.matters(p.position.x(), p.position.y(), p.velocity.x(), p.velocity.y(), p.radius)) {
      plain.push_back(p.id);
    }
  });
  std::vector<int> sifted;
  s.for_each_sifted(sieve.position, sieve, [&](const neighbour& p) { sifted.push_back(p.id); });
  ASSERT_GT(around, 2u * 128u);
  ASSERT_GT(plain.size(), 40u);
  ASSERT_LT(plain.size(), around / 2);
  EXPECT_EQ(sifted, plain);
}

// Within a cell the index keeps id order whatever order the people came in: the crowd's
// step sums forces in visiting order, so the order is part of the result.
TEST(snapshot, neighbours_in_a_cell_come_in_id_order) {
  std::vector<pedestrian_state> crowd;
  for (int k = 0; k < 60; ++k) {
    const int id = (k * 37) % 61 + 1;  // ids 1..61 shuffled
    crowd.push_back(at(id, 99.0 + 0.05 * (k % 40), 49.0 + 0.07 * (k % 25)));
  }
  snapshot s(penn(), 1, std::chrono::duration<double>{0.0}, crowd);
  std::vector<std::pair<std::pair<int, int>, int>> seen;  // ((cell x, cell y), id)
  s.for_each_near({100.0, 50.0}, [&](const neighbour& p) {
    seen.push_back({{static_cast<int>(p.position.x() / snapshot::neighbour_cell_m),
                     static_cast<int>(p.position.y() / snapshot::neighbour_cell_m)},
                    p.id});
  });
  ASSERT_EQ(seen.size(), crowd.size());
  for (std::size_t k = 1; k < seen.size(); ++k) {
    if (seen[k].first == seen[k - 1].first) {
      EXPECT_LT(seen[k - 1].second, seen[k].second);
    }
  }
}

TEST(snapshot, lines_are_ranked_by_join_tick_then_id) {
  auto a = at(7, 80, 86);
  a.counter = 0;
  a.queue_join_tick = 10;
  auto b = at(3, 80, 85);
  b.counter = 0;
  b.queue_join_tick = 12;
  auto c = at(4, 80, 84);
  c.counter = 0;
  c.queue_join_tick = 12;
  snapshot s(penn(), 20, std::chrono::duration<double>{0.0}, {a, b, c});
  EXPECT_EQ(s.queue_length(0), 3u);
  EXPECT_EQ(s.queue_rank(0, 10, 7), 0u);
  EXPECT_EQ(s.queue_rank(0, 12, 3), 1u);
  EXPECT_EQ(s.queue_rank(0, 12, 4), 2u);
  EXPECT_EQ(s.queue_rank(0, 21, 1), 3u);  // a newcomer queues behind everyone
  EXPECT_EQ(s.queue_length(1), 0u);
}

TEST(snapshot, a_seat_belongs_to_the_lowest_claimant) {
  auto a = at(8, 80, 20);
  a.seat = 4;
  auto b = at(6, 82, 20);
  b.seat = 4;
  snapshot s(penn(), 1, std::chrono::duration<double>{0.0}, {a, b});
  EXPECT_EQ(s.seat_holder(4), 6);
  EXPECT_EQ(s.seat_holder(5), -1);
}

}  // namespace
}  // namespace argus::world
