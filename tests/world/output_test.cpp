// Output helpers: the trajectories and appearances CSVs and the plan-view PNG (Fig. 1
// look-alike).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <sstream>
#include <string>

#include "config/scenario_loader.hpp"
#include "world/appearance_writer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/plan_view.hpp"
#include "world/plan_view_checks.hpp"
#include "world/trajectory_writer.hpp"

namespace argus::world {
namespace {

std::filesystem::path penn_scenario() {
  return std::filesystem::path{ARGUS_SOURCE_DIR} / "scenarios" / "penn_station.yaml";
}

TEST(trajectory_writer, writes_header_and_one_row_per_pedestrian) {
  auto where = station::load(builtin_layout_path());
  crowd_settings settings;
  settings.population = 20;
  crowd world(where, settings);
  std::ostringstream csv;
  trajectory_writer writer(csv);
  world.step();
  writer.write(*world.current());
  std::istringstream lines(csv.str());
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "tick,t,id,x,y,vx,vy,heading,activity");
  int rows = 0;
  while (std::getline(lines, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 8) << line;
    EXPECT_EQ(line.rfind("1,0.06666666666666667,", 0), 0u) << line;
  }
  EXPECT_EQ(rows, static_cast<int>(world.current()->pedestrians().size()));
}

TEST(appearance_writer, writes_each_pedestrian_once_with_the_colours_it_is_drawn_in) {
  auto where = station::load(builtin_layout_path());
  crowd_settings settings;
  settings.population = 20;
  settings.prefill = false;             // they arrive one by one...
  settings.spawn_rate_per_min = 600.0;  // ...within a few ticks of each other
  crowd world(where, settings);
  std::ostringstream csv;
  appearance_writer writer(csv);
  std::map<int, appearance> seen;
  std::map<int, std::uint64_t> arrived;
  for (int k = 0; k < 45; ++k) {
    world.step();
    writer.write(*world.current());
    for (const auto& p : world.current()->pedestrians()) {
      seen.emplace(p.id, p.look);
      arrived.emplace(p.id, world.current()->tick());
    }
  }
  ASSERT_GT(seen.size(), 5u);
  std::set<std::uint64_t> arrival_ticks;
  for (const auto& [id, tick] : arrived) arrival_ticks.insert(tick);
  ASSERT_GT(arrival_ticks.size(), 1u);
  std::istringstream lines(csv.str());
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "id,first_tick,shirt,trousers,skin,hair,height_m,girth_m");
  std::set<int> ids;
  while (std::getline(lines, line)) {
    std::istringstream row(line);
    std::string id, tick, shirt;
    std::getline(row, id, ',');
    std::getline(row, tick, ',');
    std::getline(row, shirt, ',');
    ASSERT_TRUE(ids.insert(std::stoi(id)).second) << "written twice: " << line;
    ASSERT_EQ(seen.count(std::stoi(id)), 1u) << line;
    EXPECT_EQ(std::stoull(tick), arrived.at(std::stoi(id))) << line;
    const auto& c = seen.at(std::stoi(id)).shirt;
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c.r, c.g, c.b);
    EXPECT_EQ(shirt, hex) << line;
  }
  EXPECT_EQ(ids.size(), seen.size());
}

TEST(trail_recorder, keeps_only_the_trail_length) {
  auto where = station::load(builtin_layout_path());
  crowd_settings settings;
  settings.population = 5;
  crowd world(where, settings);
  trail_recorder trails(std::chrono::duration<double>{1.0});
  for (int k = 0; k < 60; ++k) {
    world.step();
    trails.record(*world.current());
  }
  ASSERT_FALSE(trails.trails().empty());
  for (const auto& [id, trail] : trails.trails()) EXPECT_LE(trail.size(), 16u) << id;
}

TEST(plan_view, draws_the_station_with_cameras_and_pedestrians) {
  const auto scenario = config::load_scenario(penn_scenario());
  auto where = station::load(layout_path(scenario));
  auto settings = crowd_settings::from(scenario);
  crowd world(where, settings);
  trail_recorder trails(std::chrono::duration<double>{20.0});
  for (int k = 0; k < 15 * 60; ++k) {
    world.step();
    trails.record(*world.current());
  }
  const auto out = std::filesystem::path{testing::TempDir()} / "penn_station_plan.png";
  write_plan_view(out, *where, scenario.cameras, world.current().get(), &trails.trails());
  std::printf("[ plan     ] %s\n", out.c_str());
  const cv::Mat image = cv::imread(out.string());
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 200 * 7 + 48);
  EXPECT_EQ(image.rows, 100 * 7 + 48);
  // Portals are yellow (BGR 0, 215, 255): the arcade's street portal centre is.
  const cv::Vec3b portal = image.at<cv::Vec3b>(24 + (100 - 50) * 7, 24 + 199 * 7);
  EXPECT_EQ(portal, cv::Vec3b(0, 215, 255));
  // Walls, cameras, pedestrians and their trails where the station and the crowd put them.
  const auto found =
      inspect_plan_view(image, *where, scenario.cameras, *world.current(), trails.trails());
  found.print();
  ASSERT_GT(found.walls, 300);
  EXPECT_GE(found.walls_drawn, found.walls * 8 / 10);
  ASSERT_EQ(found.cameras, static_cast<int>(scenario.cameras.size()));
  EXPECT_GE(found.cameras_drawn, found.cameras - 1);
  ASSERT_GE(found.pedestrians, 50);
  EXPECT_GE(found.pedestrians_drawn, found.pedestrians * 9 / 10);
  ASSERT_GT(found.trails, 50);
  EXPECT_GE(found.trails_drawn * 3, found.trails * 2);
}

}  // namespace
}  // namespace argus::world
