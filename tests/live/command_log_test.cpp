// commands.yaml: what a live run writes, what `argus run --commands` reads back and how it puts
// the commands into the scenario for the replay.
#include "live/command_log.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "config/ticks.hpp"

namespace argus::live {
namespace {

config::scenario two_cameras() {
  config::scenario s;
  s.name = "pair";
  s.run.seed = 7;
  for (int id : {1, 2}) {
    config::camera_settings c;
    c.id = id;
    c.position = {10.0 * id, 0.0};
    s.cameras.push_back(c);
  }
  s.network.communication_range_m = 50.0;
  return s;
}

std::vector<timed_command> sample() {
  command task;
  task.kind = command_kind::task;
  task.camera = 2;
  task.pixel = {160.5, 120.0};
  task.task = 0;
  command cancel;
  cancel.kind = command_kind::cancel;
  cancel.task = 0;
  command crash;
  crash.kind = command_kind::crash;
  crash.camera = 1;
  command cut;
  cut.kind = command_kind::cut;
  cut.camera = 1;
  cut.peer = 2;
  command recover;
  recover.kind = command_kind::recover;
  recover.camera = 1;
  return {{150, task}, {150, cut}, {200, crash}, {300, cancel}, {301, recover}};
}

TEST(command_log, orders_by_tick_tasks_first) {
  command_log log;
  auto all = sample();
  log.add(all[2]);  // crash at 200, from the fault injector's thread
  log.add(all[1]);  // cut at 150 (fault injector)
  log.add(all[0]);  // task at 150 (scenario script)
  const auto got = log.commands();
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0], all[0]);
  EXPECT_EQ(got[1], all[1]);
  EXPECT_EQ(got[2], all[2]);
}

TEST(command_log, yaml_reads_back) {
  const auto all = sample();
  const auto path = std::filesystem::temp_directory_path() / "argus_command_log_test.yaml";
  {
    std::ofstream out(path);
    out << commands_yaml(all, two_cameras());
  }
  EXPECT_EQ(read_commands(path), all);
  std::filesystem::remove(path);
}

TEST(command_log, bad_file_is_named) {
  const auto path = std::filesystem::temp_directory_path() / "argus_command_log_bad.yaml";
  {
    std::ofstream out(path);
    out << "commands:\n  - {tick: 5, command: explode, camera: 1}\n";
  }
  try {
    read_commands(path);
    FAIL() << "read a bad command";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("commands[0]: unknown command 'explode'"),
              std::string::npos)
        << e.what();
  }
  std::filesystem::remove(path);
}

TEST(command_log, applies_to_the_scenario_at_the_ticks) {
  auto s = two_cameras();
  apply_commands(s, sample());
  ASSERT_EQ(s.tasks.size(), 1u);
  EXPECT_EQ(config::to_ticks(s.tasks[0].at, s.run.tick), 150);
  EXPECT_EQ(s.tasks[0].by, config::task_target::pixel);
  EXPECT_EQ(s.tasks[0].camera, 2);
  ASSERT_TRUE(s.tasks[0].cancel_at);
  EXPECT_EQ(config::to_ticks(*s.tasks[0].cancel_at, s.run.tick), 300);
  ASSERT_EQ(s.faults.size(), 3u);
  EXPECT_EQ(s.faults[0].kind, config::fault_kind::link_cut);
  EXPECT_EQ(s.faults[0].peer, 2);
  EXPECT_EQ(s.faults[1].kind, config::fault_kind::crash);
  EXPECT_EQ(config::to_ticks(s.faults[1].at, s.run.tick), 200);
  EXPECT_EQ(s.faults[2].kind, config::fault_kind::recover);
  EXPECT_EQ(config::to_ticks(s.faults[2].at, s.run.tick), 301);
}

TEST(command_log, refuses_what_does_not_fit) {
  auto s = two_cameras();
  auto all = sample();
  all[0].what.task = 4;  // the scenario has no tasks: the first must be task 0
  EXPECT_THROW(apply_commands(s, all), std::invalid_argument);
  s = two_cameras();
  all = sample();
  all[2].what.camera = 9;
  EXPECT_THROW(apply_commands(s, all), std::invalid_argument);
  s = two_cameras();
  all = sample();
  all.push_back(all[3]);  // a second cancellation of task 0
  EXPECT_THROW(apply_commands(s, all), std::invalid_argument);
}

}  // namespace
}  // namespace argus::live
