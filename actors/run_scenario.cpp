#include "actors/run_scenario.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>
#include <thread>

#include "actors/camera_world_setup.hpp"
#include "actors/clock.hpp"
#include "actors/fault_injector.hpp"
#include "actors/network_assembly.hpp"
#include "actors/operator_board.hpp"
#include "actors/participant_ids.hpp"
#include "actors/progress_printer.hpp"
#include "actors/recorder.hpp"
#include "actors/remote_network.hpp"
#include "actors/render_pool.hpp"
#include "actors/run_observer.hpp"
#include "actors/scenario_script.hpp"
#include "actors/system_config.hpp"
#include "actors/type_ids.hpp"
#include "actors/video_recorder.hpp"
#include "actors/video_tile_router.hpp"
#include "actors/wire_world.hpp"
#include "actors/worker_placement.hpp"
#include "actors/worker_pool.hpp"
#include "actors/world_coordinator.hpp"
#include "config/scenario_writer.hpp"
#include "config/ticks.hpp"
#include "config/whole_file.hpp"
#include "controller/strategy_registry.hpp"
#include "eval/metrics.hpp"
#include "eval/mot_export.hpp"
#include "eval/run_files.hpp"
#include "fmt/format.h"
#include "live/command_log.hpp"
#include "nlohmann/json.hpp"
#include "protocol/topology.hpp"
#include "spdlog/spdlog.h"
#include "world/field_cache.hpp"
#include "world/layout_loader.hpp"

namespace argus::actors {

std::filesystem::path output_dir_of(const config::scenario& scenario) {
  if (!scenario.run.output_dir.empty()) return scenario.run.output_dir;
  return std::filesystem::path("out") / (scenario.name.empty() ? "run" : scenario.name);
}

std::filesystem::path sensor_model_path(const config::scenario& scenario) {
  const std::filesystem::path file(scenario.sensing.sensor_model);
  if (file.is_absolute() || scenario.source_path.empty()) return file;
  return std::filesystem::path(scenario.source_path).parent_path() / file;
}

namespace {

// The run measured against ground truth: metrics.json and the files beside it.
void evaluate_run(const config::scenario& scenario, const world::station& station,
                  const eval::observation_log::contents& log, std::int64_t end_tick,
                  const run_options& options, run_outcome& outcome) {
  const auto& dir = outcome.output_dir;
  const double tick_s = scenario.run.tick.count();
  const auto events = eval::read_events(dir / "events.jsonl");
  outcome.evaluation = eval::evaluate(scenario, station, log, events, end_tick);
  const auto metrics = eval::metrics_json(scenario, outcome.evaluation, outcome.result.wall_seconds,
                                          outcome.result.virtual_seconds);
  config::write_whole_file(dir / "metrics.json",
                           [&](std::ostream& out) { out << metrics.dump(2) << "\n"; });
  eval::write_tracks(dir / "tracks.csv", log, tick_s);
  eval::write_targets(dir / "targets.csv", outcome.evaluation, tick_s);
  eval::write_poses(dir / "poses.csv", log, tick_s);
  if (options.mot) eval::write_mot(dir / "mot", scenario, log, end_tick);
}

// What a distributed run cannot do yet, said before anything starts (docs/distributed.md).
void check_distributable(const config::scenario& scenario) {
  auto refuse = [](const std::string& what) {
    throw std::runtime_error("--workers: " + what + " runs in one process only, for now");
  };
  if (scenario.sensing.geometry != config::group_geometry::none)
    refuse("sensing.group_geometry (cameras share a board)");
  if (scenario.sensing.reappearance != config::reappearance_model::none)
    refuse("sensing.reappearance (cameras share a board)");
  if (controller::is_oracle(scenario)) refuse("an oracle strategy (it sees every camera)");
}

// What the workers' cameras showed since the last gather, on the live console as one process's
// cameras would have put it there.
void show_on_console(live::console_state& console, live_display shown) {
  console.add_traffic(shown.sent, shown.received);
  for (auto& c : shown.cameras) {
    std::vector<cv::Rect2d> boxes;
    for (std::size_t i = 0; i + 3 < c.boxes.size(); i += 4)
      boxes.emplace_back(c.boxes[i], c.boxes[i + 1], c.boxes[i + 2], c.boxes[i + 3]);
    console.publish_camera_jpeg(c.camera, c.tick, c.pose.pan_deg, c.pose.tilt_deg,
                                c.pose.field_of_view_deg, std::move(c.jpeg), std::move(boxes));
  }
}

// What a worker needs to host its part of `scenario`: the scenario and the files it names.
worker_setup setup_for_workers(const config::scenario& scenario, const run_options& options,
                               caf::actor anchor) {
  worker_setup setup;
  setup.scenario_yaml = config::to_yaml(scenario);
  setup.layout_text = config::read_whole_file(world::layout_path(scenario));
  if (!scenario.sensing.sensor_model.empty())
    setup.sensor_model_text = config::read_whole_file(sensor_model_path(scenario));
  setup.with_visible = options.mot;
  setup.with_poses = options.video;
  if (options.video && scenario.placement.video == config::video_placement::workers)
    setup.video = {options.video_width_px, options.video_height_px, true};
  // A worker that may be lost mid-run hands its log over every tick: the evaluation keeps
  // its cameras' frames up to the loss.
  setup.stream_log = options.on_worker_loss == worker_loss::crash_nodes;
  setup.coordinator = std::move(anchor);
  setup.live = options.live != nullptr;
  return setup;
}

// An actor that only lives: the workers watch it, and end what they host when it goes. (Its
// unused argument: CAF 0.17 binds a function actor's arguments through a null tuple when there
// are none, which UBSan reports.)
caf::behavior anchor_behavior(caf::event_based_actor*, int) {
  return {[](done_atom) {}};
}

// Releases the workers' set-ups and ends the anchor they watch, unless dismissed: a run that
// fails before its world is spawned must leave nothing hosted on them, and no actor here that
// the actor system would wait for.
class set_up_guard {
 public:
  set_up_guard(caf::actor_system& system, const std::vector<worker_contact>& workers,
               const caf::actor& anchor)
      : system_(system), workers_(workers), anchor_(anchor) {}
  set_up_guard(const set_up_guard&) = delete;
  set_up_guard& operator=(const set_up_guard&) = delete;
  ~set_up_guard() {
    if (dismissed_ || workers_.empty()) return;
    if (anchor_) caf::anon_send_exit(anchor_, caf::exit_reason::user_shutdown);
    caf::scoped_actor self{system_};
    for (const auto& w : workers_) self->send(w.host, release_atom_v);
  }
  void dismiss() { dismissed_ = true; }

 private:
  caf::actor_system& system_;
  const std::vector<worker_contact>& workers_;
  const caf::actor& anchor_;
  bool dismissed_ = false;
};

// The world's first snapshot, which the crowd's spawner published before any tick, on every
// worker's board too.
void share_first_snapshot(caf::actor_system& system, const std::vector<worker_contact>& workers,
                          const world::snapshot& first) {
  caf::scoped_actor self{system};
  auto delta = delta_between(nullptr, first);
  const auto bytes = serialize(delta);
  for (const auto& w : workers) {
    std::string failure;
    self->request(w.host, std::chrono::seconds(10), board_atom_v, bytes,
                  std::vector<eval::task_origin>{})
        .receive([](done_atom) {}, [&](caf::error& err) { failure = system.render(err); });
    if (!failure.empty())
      throw std::runtime_error(fmt::format("worker {} (the first snapshot): {}", w.name, failure));
  }
}

}  // namespace

std::shared_ptr<const world::station> load_run_station(const config::scenario& scenario) {
  world::navigation_settings navigation;
  navigation.threads = scenario.run.threads;  // 0 for one per core, as the run's scheduler
  navigation.field_cache = world::field_cache::default_dir_or_none();
  auto station = world::station::load(world::layout_path(scenario), navigation);
  if (const auto& problem = station->field_cache_problem(); !problem.empty())
    spdlog::warn("the distance fields were computed but not kept for the next run: {}", problem);
  return station;
}

run_outcome run_scenario(const config::scenario& scenario, bool show_progress) {
  run_options options;
  options.show_progress = show_progress;
  return run_scenario(scenario, options);
}

run_outcome run_scenario(const config::scenario& scenario, const run_options& options) {
  // A strategy that cannot be made fails here, naming the field, before any actor runs.
  controller::resolve_strategy(scenario);
  const auto& pool_of_workers = options.workers;
  if (pool_of_workers) check_distributable(scenario);
  const bool show_progress = options.show_progress;
  auto threads = scenario.run.threads != 0 ? scenario.run.threads
                                           : std::max(1u, std::thread::hardware_concurrency());
  system_config cfg(threads);
  if (pool_of_workers) pool_of_workers->configure(cfg);
  caf::actor_system system{cfg};
  std::vector<worker_contact> workers;
  if (pool_of_workers) {
    workers = pool_of_workers->connect(system);
    greet_workers(system, workers, std::chrono::seconds(10));
  }
  const protocol::topology topo(scenario);
  // The workers set up side by side with this process: each parses the scenario and loads the
  // station while this one loads its own (docs/distributed.md, "Starting a run").
  // Lives until the workers have handed over their logs: they watch it, and end what they
  // host when it goes (with this process or its connection).
  caf::actor anchor;
  // Which worker steps each crowd partition (none: here).
  std::vector<std::optional<std::size_t>> partition_workers;
  std::vector<bool> steps_crowd(workers.size(), false);
  pending_set_up set_up;
  if (!workers.empty()) {
    anchor = system.spawn(anchor_behavior, 0);
    partition_workers = place_partitions(scenario, workers.size());
    for (const auto& w : partition_workers)
      if (w) steps_crowd[*w] = true;
    set_up = ask_workers_to_set_up(system, scenario, topo, workers,
                                   setup_for_workers(scenario, options, anchor),
                                   options.on_worker_loss, steps_crowd);
  }
  // Until the world is spawned: a run that fails leaves nothing hosted on the workers.
  set_up_guard release_set_up(system, workers, anchor);

  run_outcome outcome;
  outcome.output_dir = output_dir_of(scenario);
  const double tick_seconds = scenario.run.tick.count();

  // The station, the render pool and the video file first: when one of them fails, no other
  // actor is running yet that the actor system would wait for.
  const auto end_tick = config::to_ticks(scenario.run.duration, scenario.run.tick);
  caf::actor video_participant;
  world_run_settings world_settings;
  world_settings.station = options.station ? options.station : load_run_station(scenario);
  // Kept for the evaluation: world_settings goes to the world actors.
  const auto station = world_settings.station;
  render_pool pool;
  const std::size_t renderers = options.render_threads != 0 ? options.render_threads : threads;
  const bool video_here =
      workers.empty() || scenario.placement.video == config::video_placement::coordinator;
  if (options.video && video_here) {
    pool = spawn_render_pool(system, world_settings.station, renderers);
  } else if (options.video) {
    // Each camera's tiles are rendered by its worker; here only those of a lost worker.
    video_tile_routes routes;
    for (const auto& [camera, w] : place_cameras(scenario, workers.size()))
      routes.hosts[camera] = workers[w].host;
    routes.station = world_settings.station;
    routes.local_renderers = renderers;
    pool.front = spawn_video_tile_router(system, std::move(routes));
  }
  auto log = std::make_shared<eval::observation_log>(options.mot);
  std::shared_ptr<camera_world> cameras_world;
  if (workers.empty()) {
    try {
      vision::sensor_model model;
      if (!scenario.sensing.sensor_model.empty())
        model = vision::load_sensor_model(sensor_model_path(scenario).string());
      cameras_world =
          make_camera_world(scenario, world_settings.station, std::move(model), renderers, log);
    } catch (...) {
      if (pool.front) caf::anon_send_exit(pool.front, caf::exit_reason::user_shutdown);
      throw;
    }
  } else {
    // The cameras sense on their workers; here the board only feeds the evaluation.
    cameras_world = std::make_shared<camera_world>();
    cameras_world->station = world_settings.station;
    cameras_world->board = std::make_shared<snapshot_board>();
    for (const auto& w : workers) world_settings.remote_boards.push_back(w.host);
    world_settings.picks_gathered = [log](const std::vector<eval::task_origin>& picks) {
      for (const auto& p : picks) log->add_origin_if_new(p);
    };
    world_settings.on_worker_loss = options.on_worker_loss;
    world_settings.adopted_threads = threads;
    if (options.on_worker_loss == worker_loss::crash_nodes)
      world_settings.log_gathered = [log](eval::observation_log::contents share) {
        log->add_worker_share(std::move(share));
      };
  }
  cameras_world->board->subscribe(
      [log](const std::shared_ptr<const world::snapshot>& frame) { sample_targets(*log, *frame); });
  world_settings.board = cameras_world->board;
  const auto& live = options.live;
  std::shared_ptr<operator_board> operators;
  std::shared_ptr<live::console_state> console;
  if (live) {
    // The session outlives the run (the caller holds it): the aliases keep it alive regardless.
    operators = std::make_shared<operator_board>();
    cameras_world->operators = operators;
    console = std::shared_ptr<live::console_state>(live, &live->console);
    cameras_world->board->subscribe([console](const std::shared_ptr<const world::snapshot>& frame) {
      console->publish_snapshot(frame);
    });
  }
  if (workers.empty()) {
    cameras_world->observer = std::make_shared<run_observer>(log, console);
  } else if (live) {
    // The workers' cameras read the orders here, sent on with each snapshot, and show
    // themselves through what comes back with each gather.
    world_settings.operators = operators;
    world_settings.display_gathered = [console](live_display shown) {
      show_on_console(*console, std::move(shown));
    };
    world_settings.watched_cameras = [console] { return console->watched(); };
  }
  if (options.video) {
    video_settings vs;
    vs.file = outcome.output_dir / "video" / "feeds.avi";
    vs.cameras = scenario.cameras;
    vs.run_seed = scenario.run.seed;
    vs.tile_width_px = options.video_width_px;
    vs.tile_height_px = options.video_height_px;
    vs.tick_seconds = tick_seconds;
    vs.end_tick = end_tick;
    vs.render_pool = pool.front;
    cameras_world->poses = std::make_shared<camera_pose_board>();
    vs.poses = cameras_world->poses;
    // The cameras are on the workers: their poses come with the picks, every tick, before the
    // world's snapshot reaches the recorder.
    if (!workers.empty())
      world_settings.poses_gathered =
          [poses = cameras_world->poses](const std::vector<pose_record>& got) {
            for (const auto& r : got) poses->put(r.camera, r.tick, r.pose);
          };
    caf::actor video;
    try {
      video = spawn_video_recorder(system, std::move(vs));
    } catch (...) {
      caf::anon_send_exit(pool.front, caf::exit_reason::user_shutdown);
      throw;
    }
    world_settings.snapshot_observers.emplace_back(video, participant_ids::video_recorder);
    video_participant = video;
  }

  recorder_settings rec;
  rec.output_dir = outcome.output_dir;
  rec.scenario = scenario.name;
  rec.seed = scenario.run.seed;
  rec.tick_seconds = tick_seconds;
  rec.threads = threads;
  rec.speed = scenario.run.speed;
  if (live)
    rec.observer = [live](const std::vector<sim_event>& batch) {
      std::vector<live::event_line> lines;
      lines.reserve(batch.size());
      for (const auto& ev : batch) lines.push_back({ev.tick, ev.source, ev.kind, ev.fields_json});
      live->console.record_events(lines);
    };
  auto recorder = spawn_recorder(system, rec);

  caf::actor progress;
  if (show_progress) progress = spawn_progress_printer(system, tick_seconds);

  clock_settings cs;
  cs.end_tick = end_tick;
  cs.tick_seconds = tick_seconds;
  cs.speed = scenario.run.speed;
  if (live) cs.pacing = std::shared_ptr<pacing>(live, &live->pace);
  // Links are never ticked: the clock's round trips are the cameras'.
  cs.own_thread = clock_on_own_thread(threads, scenario.cameras.size());
  // Each worker ticks its own cameras and answers for them at once.
  for (const auto& w : workers) cs.sub_clocks[w.name] = w.host;
  cs.on_worker_loss = options.on_worker_loss;
  auto clock = spawn_clock(system, cs, recorder, progress);

  // Joins and link attachments go out from this thread, in this order, before `start`:
  // enqueued in program order, they all reach their receivers before the first tick.
  auto board = cameras_world->board;
  network_directory net;
  // Nothing has started when a worker refuses: end what did spawn here (release_set_up ends
  // what the workers host).
  const auto abandon = [&] {
    for (const auto& a : {clock, recorder, progress})
      if (a) caf::anon_send_exit(a, caf::exit_reason::user_shutdown);
  };
  for (const auto& w : partition_workers)
    world_settings.partition_hosts.push_back(w ? partition_host{workers[*w].host, workers[*w].name}
                                               : partition_host{});
  if (workers.empty()) {
    net = spawn_network(system, scenario, topo, clock, std::move(cameras_world));
  } else {
    try {
      net = spawn_remote_network(system, scenario, topo, clock, workers, std::move(set_up));
    } catch (...) {
      abandon();
      throw;
    }
  }
  auto script = spawn_scenario_script(system, scenario, clock, log, live, operators);
  caf::anon_send(clock, join_atom_v, script, script_participant(live != nullptr));
  auto faults = spawn_fault_injector(system, scenario, clock, std::move(net), live);
  caf::anon_send(clock, join_atom_v, faults, fault_injector_participant(scenario, live != nullptr));
  world_settings.crowd = world::crowd_settings::from(scenario);
  if (video_participant)
    caf::anon_send(clock, join_atom_v, video_participant, video_recorder_participant());
  world_settings.end_tick = cs.end_tick;
  world_settings.trajectories = outcome.output_dir / "trajectories.csv";
  world_actors crowd;
  try {
    crowd = spawn_world(system, std::move(world_settings));
  } catch (...) {
    for (const auto& a : {script, faults, video_participant, pool.front})
      if (a) caf::anon_send_exit(a, caf::exit_reason::user_shutdown);
    abandon();
    throw;
  }
  release_set_up.dismiss();
  for (auto& [handle, info] : crowd.participants) caf::anon_send(clock, join_atom_v, handle, info);
  // What the workers' cameras did comes with their answers in phase world, for the world.
  if (!workers.empty())
    for (auto& [handle, info] : crowd.participants)
      if (info.id == participant_ids::world_coordinator)
        caf::anon_send(clock, gather_sink_atom_v, handle);
  if (!workers.empty()) share_first_snapshot(system, workers, *board->latest());

  std::string failure;
  {
    caf::scoped_actor self{system};
    self->request(clock, caf::infinite, start_atom_v)
        .receive([&](run_result& r) { outcome.result = std::move(r); },
                 [&](caf::error& err) { failure = system.render(err); });
  }
  if (progress) caf::anon_send_exit(progress, caf::exit_reason::user_shutdown);
  // The render workers are detached threads linked to the front: end them with it.
  if (pool.front) caf::anon_send_exit(pool.front, caf::exit_reason::user_shutdown);
  if (!workers.empty()) {
    std::function<void(live_display)> shown;
    if (console)
      shown = [console](live_display last) { show_on_console(*console, std::move(last)); };
    finish_workers(system, workers, *log, std::chrono::seconds(10),
                   options.on_worker_loss == worker_loss::crash_nodes, shown);
    caf::anon_send_exit(anchor, caf::exit_reason::user_shutdown);
  }
  if (!failure.empty()) {
    caf::anon_send_exit(clock, caf::exit_reason::user_shutdown);
    caf::anon_send_exit(recorder, caf::exit_reason::user_shutdown);
    throw std::runtime_error("run failed: " + failure);
  }
  if (live) live->console.finished();
  // A live run is evaluated as its replay is: with the operator's commands in the scenario.
  auto evaluated = scenario;
  if (live) live::apply_commands(evaluated, live->log.commands());
  evaluate_run(evaluated, *station, log->take(), end_tick, options, outcome);
  outcome.station = station;
  return outcome;
}

}  // namespace argus::actors
