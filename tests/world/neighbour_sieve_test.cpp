// The neighbour sieve two at a time keeps exactly whom one at a time keeps: the crowd's step
// visits whom it keeps, so one person more or fewer changes trajectories.
#include "world/neighbour_sieve.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "world/rng.hpp"

namespace argus::world {
namespace {

struct people {
  std::vector<double> x, y, vx, vy, radius;
  neighbour_columns columns() const {
    return {x.data(), y.data(), vx.data(), vy.data(), radius.data()};
  }
  void add(double px, double py, double pvx, double pvy, double r) {
    x.push_back(px);
    y.push_back(py);
    vx.push_back(pvx);
    vy.push_back(pvy);
    radius.push_back(r);
  }
};

neighbour_sieve walker(bool turning, const vec2& direction) {
  neighbour_sieve s;
  s.position = {50.0, 20.0};
  s.direction = direction;
  s.radius = 0.22;
  s.near_gap_m = 0.45 + 1e-6;
  s.reach_squared = 4.0;
  s.look_m = 2.0 + 1e-6;
  s.lane_margin_m = 0.3 + 1e-9;
  s.turning = turning;
  return s;
}

std::vector<std::uint32_t> sifted(const neighbour_sieve& s, const people& p, std::uint32_t begin,
                                  std::uint32_t end, bool pairs) {
  std::vector<std::uint32_t> picked(end - begin);
  const auto count = pairs ? s.sift(p.columns(), begin, end, picked.data())
                           : s.sift_one_by_one(p.columns(), begin, end, picked.data());
  picked.resize(count);
  return picked;
}

TEST(neighbour_sieve, two_at_a_time_keep_whom_one_at_a_time_keep) {
  rng random(4242);
  people p;
  for (int k = 0; k < 20001; ++k) {
    p.add(50.0 + random.uniform(-2.5, 2.5), 20.0 + random.uniform(-2.5, 2.5),
          random.uniform(-1.6, 1.6), random.uniform(-1.6, 1.6), random.uniform(0.15, 0.27));
  }
  // Edges: the walker itself, someone exactly at the reach, someone at contact ahead.
  p.add(50.0, 20.0, 0.0, 0.0, 0.22);
  p.add(52.0, 20.0, -1.0, 0.0, 0.22);
  p.add(50.44, 20.0, 0.0, 0.0, 0.22);
  const auto n = static_cast<std::uint32_t>(p.x.size());
  std::size_t kept = 0;
  for (const bool turning : {false, true}) {
    for (const vec2& direction : {vec2{1.0, 0.0}, vec2{0.6, -0.8}, vec2{0.0, 0.0}}) {
      const auto s = walker(turning, direction);
      for (std::uint32_t begin : {0u, 1u, 7u}) {
        for (std::uint32_t end : {n, n - 1, begin + 1, begin}) {
          const auto one = sifted(s, p, begin, end, false);
          EXPECT_EQ(sifted(s, p, begin, end, true), one) << begin << ".." << end;
          kept += one.size();
        }
      }
    }
  }
  // Neither keeps everyone nor no one: the comparison weighs real choices.
  EXPECT_GT(kept, 200u);
  EXPECT_LT(kept, 6u * 3u * 12u * 20001u / 2u);
}

TEST(neighbour_sieve, keeps_the_near_and_those_ahead_and_not_the_walker_itself) {
  people p;
  p.add(50.0, 20.0, 0.0, 0.0, 0.22);  // the walker itself
  p.add(50.5, 20.0, 0.0, 0.0, 0.22);  // near, touching
  p.add(51.8, 20.1, 0.0, 0.0, 0.22);  // in the lane ahead, within the look-ahead
  p.add(48.5, 20.0, 0.0, 0.0, 0.22);  // behind, beyond the forces' reach
  p.add(50.0, 21.7, 0.0, 0.0, 0.22);  // beside, beyond the forces' reach
  p.add(52.5, 20.0, 0.0, 0.0, 0.22);  // ahead but past the reach
  const auto s = walker(false, {1.0, 0.0});
  EXPECT_EQ(sifted(s, p, 0, 6, true), (std::vector<std::uint32_t>{1, 2}));
}

}  // namespace
}  // namespace argus::world
