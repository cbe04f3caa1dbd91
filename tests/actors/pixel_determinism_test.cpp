// Same seed, same log, whatever the thread count, with pixel sensing: camera nodes render their
// own frames on whichever scheduler thread runs their turn (actors/shared_renderers.hpp), with
// as many renderers as threads, and each camera's imaging noise travels with its requests. A
// real multithreaded run of penn_station.yaml, with its operator's task, at 1 and 3 threads.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "actors/run_scenario.hpp"
#include "config/scenario_loader.hpp"

namespace argus::actors {
namespace {

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Runs 20 s of penn_station.yaml (seed 3) on `threads` scheduler threads; returns its folder.
std::filesystem::path run_on(unsigned threads) {
  auto s = config::load_scenario(std::filesystem::path(ARGUS_SOURCE_DIR) / "scenarios" /
                                 "penn_station.yaml");
  EXPECT_EQ(s.sensing.mode, config::sensing_mode::pixels);
  s.run.duration = config::seconds{20.0};
  s.run.seed = 3;
  s.run.threads = threads;
  s.run.output_dir = (std::filesystem::temp_directory_path() /
                      ("argus_pixel_determinism_" + std::to_string(threads)))
                         .string();
  std::filesystem::remove_all(s.run.output_dir);
  run_scenario(s, false);
  return s.run.output_dir;
}

TEST(pixel_determinism, a_pixel_run_is_the_same_on_one_thread_and_on_three) {
  const auto one = run_on(1);
  const auto three = run_on(3);
  const auto events = read_file(one / "events.jsonl");
  // The task was taken and tracked on rendered frames: there is something to compare.
  ASSERT_NE(events.find("\"kind\":\"task_created\""), std::string::npos);
  const auto tracks = read_file(one / "tracks.csv");
  ASSERT_GT(std::count(tracks.begin(), tracks.end(), '\n'), 10);
  EXPECT_EQ(events, read_file(three / "events.jsonl"));
  EXPECT_EQ(tracks, read_file(three / "tracks.csv"));
  EXPECT_EQ(read_file(one / "trajectories.csv"), read_file(three / "trajectories.csv"));
}

}  // namespace
}  // namespace argus::actors
