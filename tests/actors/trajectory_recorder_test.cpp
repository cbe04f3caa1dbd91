// The world's rows are written by an actor of their own, off the clock's path
// (actors/trajectory_recorder.hpp): every snapshot it is handed, in order, and the files named
// once whole, also when the world coordinator that handed them ends before they are written.

#include "actors/trajectory_recorder.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "actors/system_config.hpp"
#include "caf/actor_system.hpp"
#include "caf/event_based_actor.hpp"
#include "caf/scoped_actor.hpp"
#include "config/scenario.hpp"
#include "world/appearance_writer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/trajectory_writer.hpp"

namespace argus::actors {
namespace {

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A small crowd with newcomers, stepped `ticks` times: its snapshots from tick 0 on.
std::vector<std::shared_ptr<const world::snapshot>> stepped_crowd(std::int64_t ticks) {
  config::scenario s;
  s.run.seed = 5;
  s.world.population = 60;
  s.world.spawn_rate_per_min = 600;
  world::crowd crowd(world::station::load(world::layout_path(s)), world::crowd_settings::from(s));
  std::vector<std::shared_ptr<const world::snapshot>> out{crowd.current()};
  for (std::int64_t k = 0; k < ticks; ++k) {
    crowd.step();
    out.push_back(crowd.current());
  }
  return out;
}

// What the writers make of `frames`, rows and looks.
std::pair<std::string, std::string> expected_files(
    const std::vector<std::shared_ptr<const world::snapshot>>& frames) {
  std::ostringstream rows;
  std::ostringstream looks;
  world::trajectory_writer row_writer(rows);
  world::appearance_writer look_writer(looks);
  for (const auto& f : frames) {
    row_writer.write(*f);
    look_writer.write(*f);
  }
  return {rows.str(), looks.str()};
}

std::filesystem::path fresh_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("argus-rows-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(trajectory_recorder, writes_every_snapshot_in_order_and_names_the_files_at_the_last_tick) {
  const auto frames = stepped_crowd(30);
  const auto dir = fresh_dir("end");
  system_config cfg(2);
  caf::actor_system sys{cfg};
  {
    caf::scoped_actor self{sys};
    auto file = open_trajectories(dir / "trajectories.csv");
    write_trajectories(file, *frames[0], 30);
    auto rows = spawn_trajectory_recorder(self.ptr(), std::move(file), 30);
    for (std::size_t k = 1; k < frames.size(); ++k) {
      std::int64_t answered = -1;
      self->request(rows, caf::infinite, world_snapshot_atom_v, frames[k])
          .receive([&](recorded_atom, std::int64_t tick) { answered = tick; },
                   [&](caf::error& err) { FAIL() << sys.render(err); });
      EXPECT_EQ(answered, static_cast<std::int64_t>(frames[k]->tick()));
      // Named with the last tick, not before.
      EXPECT_EQ(std::filesystem::exists(dir / "trajectories.csv"), k == frames.size() - 1);
    }
  }
  sys.await_all_actors_done();
  const auto [rows, looks] = expected_files(frames);
  EXPECT_TRUE(read_all(dir / "trajectories.csv") == rows);
  EXPECT_TRUE(read_all(dir / "pedestrians.csv") == looks);
  EXPECT_FALSE(std::filesystem::exists(dir / "trajectories.csv.partial"));
  std::filesystem::remove_all(dir);
}

// Hands `frames` to a writer of its own, then ends with an error: at once, or once all are
// written. (Spawned with arguments: CAF 0.17 binds a function actor's arguments through a null
// tuple when there are none, which UBSan reports.)
caf::behavior owner_of_rows(caf::event_based_actor* self, std::shared_ptr<trajectory_file> file,
                            const std::vector<std::shared_ptr<const world::snapshot>>& frames,
                            bool wait_for_the_rows) {
  auto rows = spawn_trajectory_recorder(self, std::move(file), 1000);
  for (std::size_t k = 1; k < frames.size(); ++k)
    self->send(rows, world_snapshot_atom_v, frames[k]);
  if (!wait_for_the_rows) {
    self->quit(caf::sec::runtime_error);
    return {};
  }
  auto left = std::make_shared<std::size_t>(frames.size() - 1);
  return {[self, left](recorded_atom, std::int64_t) {
    if (--*left == 0) self->quit(caf::sec::runtime_error);
  }};
}

// The world coordinator may end, a run failing, right after handing over its last ticks, or
// long after they were written: those ticks were acknowledged, and their rows must be in the
// files it leaves, with their names. Once it ends, nothing else holds the writer.
class trajectory_recorder_owner : public ::testing::TestWithParam<bool> {};

TEST_P(trajectory_recorder_owner, that_ends_leaves_every_row_it_handed_over) {
  const bool wait_for_the_rows = GetParam();
  const auto frames = stepped_crowd(40);
  const auto dir = fresh_dir(wait_for_the_rows ? "waited" : "at-once");
  system_config cfg(2);
  caf::actor_system sys{cfg};
  auto file = open_trajectories(dir / "trajectories.csv");
  write_trajectories(file, *frames[0], 1000);
  sys.spawn(owner_of_rows, file, frames, wait_for_the_rows);
  file.reset();
  sys.await_all_actors_done();
  ASSERT_TRUE(std::filesystem::exists(dir / "trajectories.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "trajectories.csv.partial"));
  const auto [rows, looks] = expected_files(frames);
  const auto written = read_all(dir / "trajectories.csv");
  EXPECT_EQ(written.size(), rows.size());
  EXPECT_TRUE(written == rows);
  EXPECT_TRUE(read_all(dir / "pedestrians.csv") == looks);
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(at_once_or_once_written, trajectory_recorder_owner,
                         ::testing::Values(false, true));

}  // namespace
}  // namespace argus::actors
