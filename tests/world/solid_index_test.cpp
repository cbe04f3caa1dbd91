// The solids' index gives the answer of testing every obstacle and counter, wherever the point
// is: inside, outside, on a vertex or edge, on a cell's border, and off the plan.
#include "world/solid_index.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "world/layout_loader.hpp"
#include "world/rng.hpp"

namespace argus::world {
namespace {

bool inside_any(const layout& plan, const std::vector<const service_counter*>& counters,
                const vec2& p) {
  for (const auto& o : plan.obstacles)
    if (inside_polygon(o.polygon, p)) return true;
  for (const auto* c : counters)
    if (c->footprint.contains(p)) return true;
  return false;
}

std::vector<const service_counter*> counters_of(const layout& plan) {
  std::vector<const service_counter*> out;
  for (const auto& b : plan.ticket_booths) out.push_back(&b);
  for (const auto& m : plan.vending_machines) out.push_back(&m);
  return out;
}

// Random points over the plan and a margin around it, every solid's corners and edge midpoints,
// and points on the index's cell borders.
std::vector<vec2> probes(const layout& plan, const std::vector<const service_counter*>& counters) {
  std::vector<vec2> out;
  rng random(7);
  for (int i = 0; i < 200000; ++i)
    out.push_back(
        {random.uniform(-6.0, plan.size_m.x() + 6.0), random.uniform(-6.0, plan.size_m.y() + 6.0)});
  const auto corners = [&](const std::vector<vec2>& polygon) {
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      out.push_back(polygon[i]);
      out.push_back((polygon[i] + polygon[(i + 1) % polygon.size()]) / 2.0);
    }
  };
  for (const auto& o : plan.obstacles) corners(o.polygon);
  for (const auto* c : counters)
    corners({c->footprint.min,
             {c->footprint.max.x(), c->footprint.min.y()},
             c->footprint.max,
             {c->footprint.min.x(), c->footprint.max.y()}});
  for (double x = 0.0; x <= plan.size_m.x() + 8.0; x += 4.0)
    for (double y = 0.0; y <= plan.size_m.y() + 8.0; y += 0.5) out.push_back({x, y});
  return out;
}

void expect_same_as_every_solid(const layout& plan) {
  const auto counters = counters_of(plan);
  ASSERT_FALSE(plan.obstacles.empty() && counters.empty());
  const solid_index index(plan, counters);
  int inside = 0;
  for (const auto& p : probes(plan, counters)) {
    const bool expected = inside_any(plan, counters, p);
    ASSERT_EQ(index.inside_solid(p), expected) << plan.name << " at " << p.transpose();
    inside += expected;
  }
  EXPECT_GT(inside, 100) << "too few probes inside a solid to tell";
}

TEST(solid_index, penn_station_answers_as_every_solid_does) {
  expect_same_as_every_solid(load_layout(builtin_layout_path()));
}

TEST(solid_index, the_large_station_answers_as_every_solid_does) {
  expect_same_as_every_solid(load_layout(std::filesystem::path{ARGUS_SOURCE_DIR} / "scenarios" /
                                         "large_station_layout.yaml"));
}

TEST(solid_index, solids_reaching_past_the_plan_are_found_off_it_too) {
  layout plan;
  plan.name = "edges";
  plan.size_m = {10.0, 6.0};
  plan.obstacles.push_back({"left", {{-3.0, 1.0}, {2.0, 1.0}, {2.0, 2.0}, {-3.0, 2.0}}});
  plan.obstacles.push_back({"far", {{9.0, 5.0}, {30.0, 5.0}, {30.0, 9.0}, {9.0, 9.0}}});
  plan.obstacles.push_back({"beyond", {{40.0, 40.0}, {41.0, 40.0}, {41.0, 41.0}}});
  service_counter booth;
  booth.name = "booth";
  booth.footprint = {{4.0, 4.0}, {8.0, 4.0}};  // flat: only its edge is inside
  plan.ticket_booths.push_back(booth);
  expect_same_as_every_solid(plan);
  const solid_index index(plan, counters_of(plan));
  EXPECT_TRUE(index.inside_solid({-2.0, 1.5}));
  EXPECT_TRUE(index.inside_solid({20.0, 7.0}));
  EXPECT_TRUE(index.inside_solid({40.8, 40.2}));
  EXPECT_TRUE(index.inside_solid({6.0, 4.0}));
  EXPECT_FALSE(index.inside_solid({6.0, 4.1}));
}

}  // namespace
}  // namespace argus::world
