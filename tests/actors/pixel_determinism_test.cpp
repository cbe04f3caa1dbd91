// Same seed, same log, whatever the thread count, with pixel sensing: camera nodes render their
// own frames on whichever scheduler thread runs their turn (actors/shared_renderers.hpp), with
// as many renderers as threads, and each camera's imaging noise travels with its requests. A
// real multithreaded run of penn_station.yaml, with its operator's task, at 1 and 3 threads.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "actors/run_scenario.hpp"
#include "config/scenario_loader.hpp"
#include "tests/actors/file_text.hpp"

namespace argus::actors {
namespace {

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
  const auto events = testing::file_text(one / "events.jsonl");
  // The task was taken and tracked on rendered frames: there is something to compare.
  ASSERT_NE(events.find("\"kind\":\"task_created\""), std::string::npos);
  const auto tracks = testing::file_text(one / "tracks.csv");
  ASSERT_GT(std::count(tracks.begin(), tracks.end(), '\n'), 10);
  EXPECT_EQ(events, testing::file_text(three / "events.jsonl"));
  EXPECT_EQ(tracks, testing::file_text(three / "tracks.csv"));
  EXPECT_EQ(testing::file_text(one / "trajectories.csv"),
            testing::file_text(three / "trajectories.csv"));
}

}  // namespace
}  // namespace argus::actors
