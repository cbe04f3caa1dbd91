// How pedestrians are dressed: the palettes with their near-twins, or varied clothes.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>
#include <vector>

#include "world/behaviour.hpp"

namespace argus::world {
namespace {

std::vector<appearance> crowd_of(int count, config::clothing clothes) {
  std::vector<appearance> out;
  for (int id = 1; id <= count; ++id)
    out.push_back(make_pedestrian(id, 11, {0, 0}, 0, -1, {}, clothes).state.look);
  return out;
}

double distance(const rgb8& a, const rgb8& b) {
  return std::hypot(a.r - b.r, a.g - b.g, a.b - b.b);
}

// Pairs whose shirts and trousers are each within 30 (RGB): dressed alike to colour indexing.
int alike_pairs(const std::vector<appearance>& people) {
  int alike = 0;
  for (std::size_t i = 0; i < people.size(); ++i)
    for (std::size_t j = i + 1; j < people.size(); ++j)
      alike += distance(people[i].shirt, people[j].shirt) <= 30 &&
               distance(people[i].trousers, people[j].trousers) <= 30;
  return alike;
}

std::set<std::tuple<int, int, int>> shirts_of(const std::vector<appearance>& people) {
  std::set<std::tuple<int, int, int>> out;
  for (const auto& p : people) out.insert({p.shirt.r, p.shirt.g, p.shirt.b});
  return out;
}

TEST(clothing, the_palette_is_the_default_and_holds_sixteen_shirts) {
  const auto palette = crowd_of(300, config::clothing::palette);
  for (int id = 1; id <= 20; ++id)
    EXPECT_EQ(make_pedestrian(id, 11, {0, 0}, 0, -1).state.look, palette[id - 1]) << id;
  EXPECT_LE(shirts_of(palette).size(), 16u);
}

TEST(clothing, varied_clothes_are_seldom_alike) {
  const auto palette = crowd_of(300, config::clothing::palette);
  const auto varied = crowd_of(300, config::clothing::varied);
  EXPECT_GT(shirts_of(varied).size(), 290u);
  const int alike_in_palette = alike_pairs(palette);
  const int alike_varied = alike_pairs(varied);
  std::printf("pairs dressed alike among 300: palette %d, varied %d\n", alike_in_palette,
              alike_varied);
  EXPECT_LT(alike_varied * 5, alike_in_palette);
  // Skin and hair stay drawn from their palettes (300 palette draws hold every entry).
  std::set<std::tuple<int, int, int>> skins, hairs;
  for (const auto& p : palette) {
    skins.insert({p.skin.r, p.skin.g, p.skin.b});
    hairs.insert({p.hair.r, p.hair.g, p.hair.b});
  }
  for (const auto& p : varied) {
    EXPECT_EQ(skins.count({p.skin.r, p.skin.g, p.skin.b}), 1u);
    EXPECT_EQ(hairs.count({p.hair.r, p.hair.g, p.hair.b}), 1u);
  }
}

TEST(clothing, varied_colours_span_the_hues) {
  // A shirt for each sixth of the hue circle: red, yellow, green, cyan, blue, magenta dominant.
  std::set<int> sextants;
  for (const auto& p : crowd_of(300, config::clothing::varied)) {
    const auto& c = p.shirt;
    const int top = std::max({c.r, c.g, c.b});
    const int low = std::min({c.r, c.g, c.b});
    if (top - low < 40) continue;  // too grey to say
    const int mid = c.r + c.g + c.b - top - low;
    const bool r = c.r == top, g = c.g == top, b = c.b == top;
    const bool second_r = c.r == mid, second_g = c.g == mid;
    sextants.insert(r ? (second_g ? 0 : 5) : g ? (second_r ? 1 : 2) : b ? (second_g ? 3 : 4) : -1);
  }
  EXPECT_EQ(sextants, (std::set<int>{0, 1, 2, 3, 4, 5}));
}

}  // namespace
}  // namespace argus::world
