#include "protocol/topology.hpp"

#include <gtest/gtest.h>

namespace argus::protocol {
namespace {

config::scenario three() {
  config::scenario s;
  for (auto [id, x] : {std::pair{1, 0.0}, {2, 30.0}, {3, 70.0}}) {
    config::camera_settings c;
    c.id = id;
    c.position = {x, 0.0};
    s.cameras.push_back(c);
  }
  return s;
}

TEST(topology, neighbours_are_the_cameras_within_communication_range) {
  auto s = three();
  s.network.communication_range_m = 40.0;
  topology t(s);
  EXPECT_EQ(t.links(), (std::vector<std::pair<int, int>>{{1, 2}, {2, 3}}));
  EXPECT_EQ(t.neighbours(2), (std::vector<int>{1, 3}));
  EXPECT_EQ(t.within_hops(1, 1, [](int, int) { return true; }), (std::vector<int>{2}));
  EXPECT_EQ(t.within_hops(1, 2, [](int, int) { return true; }), (std::vector<int>{2, 3}));
  // A cut between 2 and 3 partitions the network.
  auto up = [](int a, int b) { return !((a == 2 && b == 3) || (a == 3 && b == 2)); };
  EXPECT_EQ(t.within_hops(1, 3, up), (std::vector<int>{2}));
}

TEST(topology, an_explicit_adjacency_list_overrides_the_range) {
  auto s = three();
  s.network.adjacency = {{3, 1}};
  topology t(s);
  EXPECT_EQ(t.links(), (std::vector<std::pair<int, int>>{{1, 3}}));
  EXPECT_TRUE(t.neighbours(2).empty());
}

}  // namespace
}  // namespace argus::protocol
