// A distributed run's protocol in one process (docs/distributed.md): worker hosts spawned in the
// run's own actor system stand in for `argus worker`, so the placement, the hand-over of the
// world and the picks, the remote spawns and recoveries and the logs' return are checked here,
// under the sanitizers too; tests/apps/distributed_loopback.cmake runs the same over the
// middleman between processes.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/videoio.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "actors/remote_network.hpp"
#include "actors/run_scenario.hpp"
#include "actors/system_config.hpp"
#include "actors/type_ids.hpp"
#include "actors/worker_host.hpp"
#include "actors/worker_pool.hpp"
#include "config/scenario_loader.hpp"
#include "config/scenario_writer.hpp"
#include "live/session.hpp"
#include "tests/actors/file_text.hpp"
#include "world/layout_loader.hpp"

namespace argus::actors::testing {
namespace {

// Worker hosts in the run's own actor system, one per name.
class local_workers final : public worker_pool {
 public:
  explicit local_workers(std::size_t count) : count_(count) {}
  void configure(caf::actor_system_config&) const override {}
  std::vector<worker_contact> connect(caf::actor_system& system) const override {
    std::vector<worker_contact> out;
    for (std::size_t i = 0; i < count_; ++i) {
      auto name = "local-" + std::to_string(i + 1);
      out.push_back({name, spawn_worker_host(system, name, 1)});
    }
    return out;
  }

 private:
  std::size_t count_;
};

// Waits (polling every 5 ms) until `dir` holds a run's first events, then ends `victim` as a
// broken connection ends a remote worker: every proxy of it goes with
// `remote_link_unreachable`. It gives up once the run is over (events.jsonl has its name) or
// after 60 s. It lives in the run's own actor system, so no handle outlives it.
caf::behavior saboteur(caf::event_based_actor* self, caf::actor victim, std::filesystem::path dir,
                       int polls_left) {
  self->send(self, tick_atom_v, std::int64_t{0}, std::uint8_t{0}, std::uint32_t{0});
  return {
      [=](tick_atom, std::int64_t, std::uint8_t, std::uint32_t) mutable {
        std::error_code ec;
        const auto size = std::filesystem::file_size(dir / "events.jsonl.partial", ec);
        if (!ec && size > 0) {
          self->send_exit(victim, caf::exit_reason::remote_link_unreachable);
          self->quit();
        } else if (--polls_left <= 0 || std::filesystem::exists(dir / "events.jsonl")) {
          self->quit();
        } else {
          self->delayed_send(self, std::chrono::milliseconds(5), tick_atom_v, std::int64_t{0},
                             std::uint8_t{0}, std::uint32_t{0});
        }
      },
  };
}

// Two local workers, the second ended by a saboteur once the run in `dir` has written events.
class losing_workers final : public worker_pool {
 public:
  explicit losing_workers(std::filesystem::path dir) : dir_(std::move(dir)) {}
  void configure(caf::actor_system_config&) const override {}
  std::vector<worker_contact> connect(caf::actor_system& system) const override {
    std::vector<worker_contact> out{{"local-1", spawn_worker_host(system, "local-1", 1)},
                                    {"local-2", spawn_worker_host(system, "local-2", 1)}};
    system.spawn(saboteur, out[1].host, dir_, 60 * 200);
    return out;
  }

 private:
  std::filesystem::path dir_;
};

// replay_faults.yaml's first 36 s (two tasks, crashes and three recoveries, cuts, loss bursts),
// with the shipped emulated sensor: pixels cross processes in tests/apps/distributed_loopback.sh,
// and here the sanitizers must finish too.
config::scenario replay_faults(const std::filesystem::path& out) {
  const auto scenarios = std::filesystem::path(ARGUS_SOURCE_DIR) / "scenarios";
  auto s = config::load_scenario(scenarios / "replay_faults.yaml");
  s.sensing.mode = config::sensing_mode::emulated;
  s.sensing.sensor_model = (scenarios / "sensor_model.yaml").string();
  s.run.seed = 12;  // a group forms and hands over in these 36 s
  s.run.duration = config::seconds{36.0};
  s.run.threads = 2;
  s.run.output_dir = out.string();
  return s;
}

// The files a distributed run must write as one process does; metrics.json without its wall
// time, which no two runs share.
std::string outputs(const std::filesystem::path& dir) {
  // metrics.json has one member a line: leave out the two that hold the wall time.
  std::istringstream lines(file_text(dir / "metrics.json"));
  std::string metrics;
  for (std::string line; std::getline(lines, line);)
    if (line.find("\"wall_seconds\"") == std::string::npos &&
        line.find("\"speed_ratio\"") == std::string::npos)
      metrics += line + "\n";
  return file_text(dir / "events.jsonl") + "\n--\n" + file_text(dir / "trajectories.csv") +
         "\n--\n" + file_text(dir / "poses.csv") + "\n--\n" + file_text(dir / "tracks.csv") +
         "\n--\n" + metrics;
}

std::filesystem::path scratch(const std::string& tag) {
  auto dir = std::filesystem::temp_directory_path() /
             ("argus-distributed-" + std::to_string(::getpid()) + "-" + tag);
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(distributed, one_two_and_three_workers_write_what_one_process_writes) {
  const auto alone_dir = scratch("alone");
  run_scenario(replay_faults(alone_dir), run_options{});
  const auto alone = outputs(alone_dir);
  // The run has what must survive the split: crashes, a recovery, a task and its group.
  const auto events = file_text(alone_dir / "events.jsonl");
  ASSERT_NE(events.find("\"kind\":\"node_recovered\""), std::string::npos);
  ASSERT_NE(events.find("\"kind\":\"joined\""), std::string::npos);
  ASSERT_NE(events.find("\"kind\":\"handoff\""), std::string::npos);
  struct split {
    std::size_t workers;
    config::placement_policy how;
    // Under crash_nodes the links between workers run here and the logs come every tick.
    worker_loss on_loss;
    // The crowd's partitions step on the workers (two of three host one) or here.
    config::crowd_placement crowd;
    unsigned partitions;
  };
  using enum config::crowd_placement;
  const std::vector<split> splits{
      {1, config::placement_policy::region, worker_loss::end_run, workers, 2},
      {2, config::placement_policy::region, worker_loss::end_run, workers, 2},
      {3, config::placement_policy::region, worker_loss::end_run, workers, 2},
      {3, config::placement_policy::id, worker_loss::end_run, workers, 5},
      {2, config::placement_policy::id, worker_loss::end_run, coordinator, 2},
      {3, config::placement_policy::id, worker_loss::crash_nodes, workers, 2}};
  for (const auto& [n, how, on_loss, crowd, partitions] : splits) {
    const auto dir = scratch("w" + std::to_string(n));
    run_options options;
    options.workers = std::make_shared<local_workers>(n);
    options.on_worker_loss = on_loss;
    auto s = replay_faults(dir);
    s.placement.policy = how;
    s.placement.crowd = crowd;
    // The partitions do not change the run (world::partition_step): more than two put some
    // hand-overs between two partitions of one worker.
    s.world.partitions = partitions;
    auto outcome = run_scenario(s, options);
    EXPECT_TRUE(outcome.result.failure.empty()) << outcome.result.failure;
    EXPECT_TRUE(outcome.result.lost_workers.empty());
    EXPECT_EQ(outputs(dir), alone)
        << n << " workers, placement " << static_cast<int>(how) << ", on loss "
        << static_cast<int>(on_loss) << ", crowd " << static_cast<int>(crowd) << ", " << partitions
        << " partitions";
    std::filesystem::remove_all(dir);
  }
  std::filesystem::remove_all(alone_dir);
}

TEST(distributed, a_camera_crashed_and_recovered_in_one_tick_comes_back_on_its_worker) {
  // The old node's end may reach its worker after the new one took its place at the clock.
  auto with_faults = [](const std::filesystem::path& dir) {
    auto s = replay_faults(dir);
    s.run.duration = config::seconds{12.0};
    for (auto kind : {config::fault_kind::crash, config::fault_kind::recover}) {
      config::fault f;
      f.at = config::seconds{3.0};
      f.kind = kind;
      f.camera = 7;
      s.faults.push_back(f);
    }
    return s;
  };
  const auto alone_dir = scratch("race-alone");
  run_scenario(with_faults(alone_dir), run_options{});
  const auto dir = scratch("race-two");
  run_options options;
  options.workers = std::make_shared<local_workers>(2);
  auto outcome = run_scenario(with_faults(dir), options);
  EXPECT_TRUE(outcome.result.failure.empty()) << outcome.result.failure;
  EXPECT_EQ(outputs(dir), outputs(alone_dir));
  EXPECT_NE(file_text(dir / "events.jsonl").find("\"kind\":\"node_recovered\",\"camera\":7"),
            std::string::npos);
  std::filesystem::remove_all(alone_dir);
  std::filesystem::remove_all(dir);
}

TEST(distributed, two_workers_record_the_video_one_process_records) {
  // The cameras move on their workers, which render their tiles; the coordinator tiles them.
  auto with_video = [](const std::filesystem::path& dir) {
    auto s = replay_faults(dir);
    s.run.duration = config::seconds{14.0};
    return s;
  };
  run_options options;
  options.video = true;
  options.video_width_px = 80;
  options.video_height_px = 60;
  const auto alone_dir = scratch("video-alone");
  run_scenario(with_video(alone_dir), options);
  const auto alone = file_text(alone_dir / "video" / "feeds.avi");
  ASSERT_GT(alone.size(), 10000u);
  // A group formed: some camera turned to its target, so the poses are not all the defaults.
  ASSERT_NE(file_text(alone_dir / "events.jsonl").find("\"kind\":\"joined\""), std::string::npos);
  const auto dir = scratch("video-two");
  options.workers = std::make_shared<local_workers>(2);
  auto outcome = run_scenario(with_video(dir), options);
  EXPECT_TRUE(outcome.result.failure.empty()) << outcome.result.failure;
  EXPECT_TRUE(file_text(dir / "video" / "feeds.avi") == alone)
      << "the video of 2 workers differs from one process's";
  EXPECT_EQ(outputs(dir), outputs(alone_dir));
  // The same video again with every tile rendered on the coordinator.
  const auto here_dir = scratch("video-here");
  auto here = with_video(here_dir);
  here.placement.video = config::video_placement::coordinator;
  outcome = run_scenario(here, options);
  EXPECT_TRUE(outcome.result.failure.empty()) << outcome.result.failure;
  EXPECT_TRUE(file_text(here_dir / "video" / "feeds.avi") == alone)
      << "the video rendered on the coordinator differs from one process's";
  for (const auto& d : {alone_dir, dir, here_dir}) std::filesystem::remove_all(d);
}

// A live run (argus serve) of replay_faults.yaml's first 14 s, alone or on `workers`, with an
// operator's click on camera 7 and a crash of camera 3 queued before its first tick (so any run
// takes them at tick 0); returns its session.
std::shared_ptr<live::session> live_run(const std::filesystem::path& dir,
                                        std::shared_ptr<const worker_pool> workers) {
  auto s = replay_faults(dir);
  s.run.duration = config::seconds{14.0};
  auto session = std::make_shared<live::session>(s, 0.0);
  live::command click;
  click.kind = live::command_kind::task;
  click.camera = 7;
  click.pixel = {80.0, 70.0};
  click.cameras_wanted = 2;
  live::command crash;
  crash.kind = live::command_kind::crash;
  crash.camera = 3;
  EXPECT_TRUE(session->queue.push(click) && session->queue.push(crash));
  run_options options;
  options.live = session;
  options.workers = std::move(workers);
  auto outcome = run_scenario(s, options);
  EXPECT_TRUE(outcome.result.failure.empty()) << outcome.result.failure;
  return session;
}

TEST(distributed, a_live_run_on_workers_takes_the_operators_orders_as_one_process_does) {
  // The orders go out to the workers' cameras with the world's snapshot; their poses and traffic
  // come back to the console with the gathers.
  const auto alone_dir = scratch("live-alone");
  const auto alone = live_run(alone_dir, nullptr);
  const auto events = file_text(alone_dir / "events.jsonl");
  ASSERT_NE(events.find("\"kind\":\"task_issued\",\"task\":2,\"by\":\"pixel\""), std::string::npos);
  // The click resolved on camera 7 (to someone or no one), in its node's turn.
  ASSERT_NE(events.find("\"task\":2,"), events.rfind("\"task\":2,"));
  const auto dir = scratch("live-two");
  const auto shared = live_run(dir, std::make_shared<local_workers>(2));
  EXPECT_EQ(outputs(dir), outputs(alone_dir));
  EXPECT_EQ(alone->log.commands(), shared->log.commands());
  // What the page shows: the workers' traffic, and the poses their cameras turned to (camera 7
  // zooms on its target), one tick behind one process's (they come with the next gather) while
  // the run goes, and the same as one process's once it is over (the last turns come with the
  // workers' logs).
  const auto shown = shared->console.state_json();
  EXPECT_GT(shown["messages"]["sent"].get<std::uint64_t>(), 0u);
  EXPECT_GT(shown["messages"]["received"].get<std::uint64_t>(), 0u);
  const auto s = replay_faults(dir);
  int turned = 0;
  for (const auto& c : s.cameras) {
    const auto pose = shared->console.pose(c.id);
    ASSERT_TRUE(pose.has_value());
    if (pose->pan_deg != c.pan_deg || pose->tilt_deg != c.tilt_deg ||
        pose->field_of_view_deg != c.field_of_view_deg)
      ++turned;
  }
  EXPECT_GT(turned, 0) << "no camera's pose on the workers reached the console";
  for (const auto& c : s.cameras) {
    const auto last = shared->console.pose(c.id);
    const auto alone_last = alone->console.pose(c.id);
    EXPECT_TRUE(last->pan_deg == alone_last->pan_deg && last->tilt_deg == alone_last->tilt_deg &&
                last->field_of_view_deg == alone_last->field_of_view_deg)
        << "camera " << c.id << ": its last pose on the console is not one process's";
  }
  std::filesystem::remove_all(alone_dir);
  std::filesystem::remove_all(dir);
}

// penn_station_emulated.yaml (2 minutes unless told), with two local workers of which the second is
// lost in mid-run, wherever the threads put the loss.
run_outcome run_losing_a_worker(const std::filesystem::path& dir, worker_loss on_loss,
                                run_options options = {},
                                config::seconds duration = config::seconds{120.0}) {
  auto s = config::load_scenario(std::filesystem::path(ARGUS_SOURCE_DIR) / "scenarios" /
                                 "penn_station_emulated.yaml");
  s.run.seed = 5;
  s.run.duration = duration;
  s.run.threads = 2;
  s.run.output_dir = dir.string();
  options.workers = std::make_shared<losing_workers>(dir);
  options.on_worker_loss = on_loss;
  return run_scenario(s, options);
}

TEST(distributed, a_lost_worker_ends_the_run_or_its_cameras_crash) {
  const auto ended_dir = scratch("lost-end");
  auto ended = run_losing_a_worker(ended_dir, worker_loss::end_run);
  EXPECT_NE(ended.result.failure.find("worker local-2 was lost during tick"), std::string::npos)
      << ended.result.failure;
  EXPECT_LT(ended.result.ticks, 1800);
  std::filesystem::remove_all(ended_dir);

  const auto dir = scratch("lost-crash");
  auto outcome = run_losing_a_worker(dir, worker_loss::crash_nodes);
  EXPECT_TRUE(outcome.result.failure.empty()) << outcome.result.failure;
  EXPECT_EQ(outcome.result.ticks, 1800);
  ASSERT_EQ(outcome.result.lost_workers.size(), 1u);
  EXPECT_EQ(outcome.result.lost_workers[0].rfind("local-2 at tick ", 0), 0u)
      << outcome.result.lost_workers[0];
  // Every camera of the second worker is down, and none of the first's.
  const auto where =
      place_cameras(config::load_scenario(std::filesystem::path(ARGUS_SOURCE_DIR) / "scenarios" /
                                          "penn_station_emulated.yaml"),
                    2);
  const auto events = file_text(dir / "events.jsonl");
  for (const auto& [camera, worker] : where) {
    const auto line = "\"fault\":\"worker_lost\",\"camera\":" + std::to_string(camera) + ",";
    EXPECT_EQ(events.find(line) != std::string::npos, worker == 1) << "camera " << camera;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "metrics.json"));
  // Its crowd partitions (2 and 3 of 4) step on here from their last checkpoints: the crowd
  // is the one one process steps, to the last tick.
  for (const auto* line : {R"("kind":"world_partition_adopted","partition":2,"worker":"local-2")",
                           R"("kind":"world_partition_adopted","partition":3,"worker":"local-2")"})
    EXPECT_NE(events.find(line), std::string::npos) << line;
  EXPECT_EQ(events.find("world_partitions_missing"), std::string::npos);
  const auto alone_dir = scratch("lost-crash-alone");
  auto alone = config::load_scenario(std::filesystem::path(ARGUS_SOURCE_DIR) / "scenarios" /
                                     "penn_station_emulated.yaml");
  alone.run.seed = 5;
  alone.run.duration = config::seconds{120.0};
  alone.run.threads = 2;
  alone.run.output_dir = alone_dir.string();
  run_scenario(alone, {});
  const auto crowd_alone = file_text(alone_dir / "trajectories.csv");
  EXPECT_GT(crowd_alone.size(), 1000000u);
  EXPECT_TRUE(file_text(dir / "trajectories.csv") == crowd_alone)
      << "the crowd after the loss is not one process's crowd";
  EXPECT_TRUE(file_text(dir / "pedestrians.csv") == file_text(alone_dir / "pedestrians.csv"));
  std::filesystem::remove_all(alone_dir);
  std::filesystem::remove_all(dir);
}

TEST(distributed, a_lost_workers_cameras_stay_in_the_video) {
  // Each worker renders its cameras' tiles; the lost one's are rendered by the coordinator
  // from then on, so the video keeps one whole frame a tick.
  const auto dir = scratch("video-lost");
  run_options options;
  options.video = true;
  options.video_width_px = 48;
  options.video_height_px = 36;
  // The worker goes once the recorder has written events (after tick 500 or so).
  auto outcome = run_losing_a_worker(dir, worker_loss::crash_nodes, options, config::seconds{50.0});
  EXPECT_TRUE(outcome.result.failure.empty()) << outcome.result.failure;
  ASSERT_EQ(outcome.result.lost_workers.size(), 1u) << "the worker was not lost in the run";
  const auto events = file_text(dir / "events.jsonl");
  EXPECT_EQ(events.find("video_render_failed"), std::string::npos);
  EXPECT_EQ(events.find("video_out_of_step"), std::string::npos);
  cv::VideoCapture video((dir / "video" / "feeds.avi").string());
  ASSERT_TRUE(video.isOpened());
  EXPECT_EQ(video.get(cv::CAP_PROP_FRAME_COUNT), static_cast<double>(outcome.result.ticks));
  std::filesystem::remove_all(dir);
}

TEST(distributed, what_one_process_cannot_share_is_refused_before_the_run) {
  auto s = replay_faults(scratch("refused"));
  s.sensing.geometry = config::group_geometry::ground_truth;
  run_options options;
  options.workers = std::make_shared<local_workers>(2);
  try {
    run_scenario(s, options);
    FAIL() << "a shared board across workers was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("sensing.group_geometry"), std::string::npos) << e.what();
  }
}

// The workers set up while the coordinator loads its station and spawns its actors: a failure
// here after they were asked ends the run at once with its own message, not a worker's, and the
// actor system does not wait for what they were asked to host.
TEST(distributed, a_run_that_fails_here_while_the_workers_set_up_ends_with_its_own_error) {
  const auto dir = scratch("fails_here");
  std::filesystem::create_directories(dir);
  auto s = replay_faults(dir / "a file, not a folder");
  { std::ofstream(s.run.output_dir) << "in the way"; }
  run_options options;
  options.workers = std::make_shared<local_workers>(2);
  options.video = true;
  try {
    run_scenario(s, options);
    FAIL() << "a video file that cannot be written was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("a file, not a folder"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(distributed, placement_gives_every_worker_a_run_of_neighbours) {
  auto s = replay_faults(scratch("placement"));
  for (std::size_t n = 1; n <= s.cameras.size(); ++n)
    for (auto how : {config::placement_policy::region, config::placement_policy::id}) {
      s.placement.policy = how;
      auto where = place_cameras(s, n);
      ASSERT_EQ(where.size(), s.cameras.size());
      std::map<std::size_t, std::size_t> load;
      for (const auto& [camera, worker] : where) ++load[worker];
      ASSERT_EQ(load.size(), n) << "a worker without cameras";
      for (const auto& [worker, count] : load) {
        EXPECT_GE(count, s.cameras.size() / n);
        EXPECT_LE(count, s.cameras.size() / n + 1);
      }
    }
  // By id: consecutive ids together.
  s.placement.policy = config::placement_policy::id;
  auto by_id = place_cameras(s, 2);
  std::vector<int> ids;
  for (const auto& c : s.cameras) ids.push_back(c.id);
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(by_id.at(ids.front()), 0u);
  EXPECT_EQ(by_id.at(ids.back()), 1u);
  EXPECT_THROW(place_cameras(s, s.cameras.size() + 1), std::invalid_argument);
}

TEST(distributed, crowd_partitions_go_to_the_workers_in_blocks_of_strips) {
  auto s = replay_faults(scratch("crowd-placement"));
  using w = std::optional<std::size_t>;
  s.world.partitions = 8;
  EXPECT_EQ(place_partitions(s, 2), (std::vector<w>{0u, 0u, 0u, 0u, 1u, 1u, 1u, 1u}));
  EXPECT_EQ(place_partitions(s, 3), (std::vector<w>{0u, 0u, 0u, 1u, 1u, 1u, 2u, 2u}));
  s.world.partitions = 2;
  EXPECT_EQ(place_partitions(s, 4), (std::vector<w>{0u, 2u}));
  // Here when asked.
  s.placement.crowd = config::crowd_placement::coordinator;
  EXPECT_EQ(place_partitions(s, 4), (std::vector<w>{w{}, w{}}));
}

TEST(distributed, a_worker_set_up_without_the_crowd_refuses_a_partition) {
  system_config cfg(1);
  caf::actor_system system{cfg};
  auto host = spawn_worker_host(system, "local-1", 1);
  const auto s = replay_faults(scratch("no-crowd"));
  worker_setup setup;
  setup.scenario_yaml = config::to_yaml(s);
  setup.layout_text = file_text(world::layout_path(s));
  caf::scoped_actor self{system};
  std::string failure;
  self->request(host, std::chrono::seconds(30), worker_setup_atom_v, setup)
      .receive([](std::vector<caf::actor>&) {},
               [&](caf::error& err) { failure = system.render(err); });
  ASSERT_EQ(failure, "");
  self->request(host, std::chrono::seconds(30), spawn_partition_atom_v, partition_placement{})
      .receive([](caf::actor&) {}, [&](caf::error& err) { failure = system.render(err); });
  EXPECT_NE(failure.find("not set up to step the crowd"), std::string::npos) << failure;
  self->send_exit(host, caf::exit_reason::user_shutdown);
}

TEST(distributed, a_worker_of_another_version_is_refused_naming_both) {
  system_config cfg(1);
  caf::actor_system system{cfg};
  auto host = spawn_worker_host(system, "w-old", 1);
  caf::scoped_actor self{system};
  std::string refusal;
  self->request(host, std::chrono::seconds(5), worker_hello_atom_v, std::string("0.0.1"))
      .receive([&](std::string&, std::string&) {},
               [&](caf::error& err) { refusal = system.render(err); });
  EXPECT_NE(refusal.find("w-old"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("0.0.1"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find(argus_version()), std::string::npos) << refusal;
  EXPECT_NO_THROW(greet_workers(system, {{"w-same", host}}, std::chrono::seconds(5)));
  caf::anon_send_exit(host, caf::exit_reason::user_shutdown);
}

}  // namespace
}  // namespace argus::actors::testing
