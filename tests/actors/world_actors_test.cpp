// The crowd-partition actors reproduce world::crowd, the single-threaded reference, byte for
// byte: the same trajectories.csv for 1 and 4 partitions on 1 and 2 scheduler threads.
//
//   clock tick t:  [world]   partition 0 .. n-1 step from snapshot t --report--> coordinator
//                  [network] coordinator: gather, spawn, merge snapshot t + 1, write a row
//                            per pedestrian --update (snapshot, pedestrians)--> partitions

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "actors/run_scenario.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/trajectory_writer.hpp"

namespace argus::actors {
namespace {

constexpr double duration_s = 8.0;  // 120 ticks at 15 Hz

config::scenario crowd_only(const std::filesystem::path& out, unsigned partitions,
                            unsigned threads) {
  config::scenario s;
  s.name = "crowd";
  s.run.seed = 11;
  s.run.duration = config::seconds{duration_s};
  s.run.threads = threads;
  s.run.output_dir = out.string();
  s.world.population = 150;
  s.world.spawn_rate_per_min = 600;  // newcomers keep arriving while people leave
  s.world.partitions = partitions;
  return s;
}

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// world::crowd stepped directly for the same ticks (the partition count does not matter).
std::string reference_trajectories(const config::scenario& s, std::int64_t ticks) {
  world::crowd reference(world::station::load(world::layout_path(s)),
                         world::crowd_settings::from(s));
  std::ostringstream out;
  world::trajectory_writer writer(out);
  writer.write(*reference.current());
  for (std::int64_t k = 0; k < ticks; ++k) {
    reference.step();
    writer.write(*reference.current());
  }
  return out.str();
}

class world_actors : public ::testing::TestWithParam<std::pair<unsigned, unsigned>> {};

TEST_P(world_actors, write_the_same_trajectories_as_the_reference_crowd) {
  auto [partitions, threads] = GetParam();
  auto dir = std::filesystem::temp_directory_path() /
             ("argus-world-" + std::to_string(::getpid()) + "-" + std::to_string(partitions) + "-" +
              std::to_string(threads));
  std::filesystem::remove_all(dir);
  auto scenario = crowd_only(dir, partitions, threads);
  auto outcome = run_scenario(scenario, false);
  ASSERT_EQ(outcome.result.ticks, 120);
  EXPECT_TRUE(outcome.result.unexpected_down.empty());
  ASSERT_TRUE(std::filesystem::exists(dir / "trajectories.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "trajectories.csv.partial"));
  static const auto expected = reference_trajectories(scenario, 120);
  const auto actual = read_all(dir / "trajectories.csv");
  EXPECT_EQ(actual.size(), expected.size());
  EXPECT_TRUE(actual == expected) << "trajectories differ from world::crowd";
  // Newcomers arrived and people left: the exchange between actors was exercised.
  EXPECT_GT(outcome.result.events_by_kind["pedestrian_entered"], 0);
  EXPECT_GT(outcome.result.events_by_kind["goal_completed"], 0);
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(partitions_and_threads, world_actors,
                         ::testing::Values(std::pair{1u, 1u}, std::pair{1u, 2u}, std::pair{4u, 1u},
                                           std::pair{4u, 2u}));

}  // namespace
}  // namespace argus::actors
