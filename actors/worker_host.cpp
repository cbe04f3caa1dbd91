#include "actors/worker_host.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "actors/camera_node.hpp"
#include "actors/camera_pose_board.hpp"
#include "actors/camera_world_setup.hpp"
#include "actors/crowd_partition.hpp"
#include "actors/display_relay.hpp"
#include "actors/link.hpp"
#include "actors/participant_ids.hpp"
#include "actors/phase.hpp"
#include "actors/render_pool.hpp"
#include "actors/run_observer.hpp"
#include "actors/type_ids.hpp"
#include "actors/video_tiles.hpp"
#include "config/scenario_loader.hpp"
#include "controller/strategy_registry.hpp"
#include "fmt/format.h"
#include "spdlog/spdlog.h"
#include "world/crowd.hpp"
#include "world/field_cache.hpp"

namespace argus::actors {

const char* argus_version() {
  return ARGUS_VERSION;
}

namespace {

// The picks a worker's cameras made since the coordinator last asked; cameras add from their
// turns, on any thread.
class pick_outbox {
 public:
  void add(const eval::task_origin& o) {
    std::lock_guard<std::mutex> guard(mutex_);
    picks_.push_back(o);
  }
  std::vector<eval::task_origin> take() {
    std::lock_guard<std::mutex> guard(mutex_);
    auto out = std::move(picks_);
    picks_.clear();
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.task < b.task; });
    return out;
  }

 private:
  std::mutex mutex_;
  std::vector<eval::task_origin> picks_;
};

// The files a setup carries, written where this worker can load them, removed with the run.
class setup_files {
 public:
  setup_files() {
    std::random_device entropy;
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("argus-worker-{:016x}", (std::uint64_t{entropy()} << 32) | entropy());
    std::filesystem::create_directories(dir_);
  }
  ~setup_files() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  setup_files(const setup_files&) = delete;
  setup_files& operator=(const setup_files&) = delete;

  std::filesystem::path write(const std::string& name, const std::string& text) const {
    auto file = dir_ / name;
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + file.string());
    return file;
  }

 private:
  std::filesystem::path dir_;
};

// The phase's ticks the clock handed this worker as its sub-clock: the acks awaited, and those in.
struct tick_batch {
  caf::actor clock;
  std::uint8_t phase = 0;
  std::set<std::uint64_t> waiting;
  std::vector<tick_ack> acks;
};

struct hosted_run {
  config::scenario scenario;
  std::unique_ptr<setup_files> files;
  std::shared_ptr<eval::observation_log> log;
  bool stream_log = false;   // worker_setup::stream_log
  bool steps_crowd = false;  // worker_setup::steps_crowd
  std::shared_ptr<pick_outbox> picks;
  std::shared_ptr<camera_world> world;
  std::vector<caf::actor> spawned;
  caf::actor coordinator;
  // Its camera nodes as the clock knows them, by participant id and by address.
  std::map<std::uint64_t, caf::actor> participants;
  std::map<caf::actor_addr, std::uint64_t> participant_of;
  tick_batch batch;
  /// The last snapshot the coordinator sent: the next arrives as changes to it.
  std::shared_ptr<const world::snapshot> last;
  /// What renders the video's tiles of its cameras (worker_setup::video), when it does.
  video_tile_settings video;
  caf::actor video_renderers;
  /// Tiles sent back, and their bytes (logged when the run ends).
  std::uint64_t tiles_sent = 0;
  std::uint64_t tile_bytes_sent = 0;
  /// What the console shows of its cameras, in a live run (worker_setup::live); null otherwise.
  std::shared_ptr<display_relay> display;
};

struct worker_host_state {
  std::string name;
  std::size_t render_threads = 1;
  unsigned field_threads = 0;
  std::optional<hosted_run> run;
};

using host_actor = caf::stateful_actor<worker_host_state>;

// Says no to the coordinator that asked, and says so here too: the worker's operator sees
// who was refused and why, not only the coordinator.
caf::error refuse(caf::local_actor* self, std::string why) {
  const auto& sender = self->current_sender();
  spdlog::warn("refused {}: {}",
               sender ? "the coordinator on node " + to_string(sender->node()) : "a request", why);
  return caf::make_error(caf::sec::runtime_error, std::move(why));
}

void end_run(host_actor* self) {
  auto& st = self->state;
  if (!st.run) return;
  if (st.run->tiles_sent > 0)
    spdlog::info("worker {}: sent {} video tiles, {:.1f} MB ({:.1f} KB a tile)", st.name,
                 st.run->tiles_sent, static_cast<double>(st.run->tile_bytes_sent) / 1e6,
                 static_cast<double>(st.run->tile_bytes_sent) / 1e3 /
                     static_cast<double>(st.run->tiles_sent));
  for (auto& a : st.run->spawned) self->send_exit(a, caf::exit_reason::user_shutdown);
  st.run.reset();
}

caf::result<std::vector<caf::actor>> set_up(host_actor* self, worker_setup& setup) {
  auto& st = self->state;
  if (st.run) return refuse(self, fmt::format("worker {} is busy with another run", st.name));
  try {
    hosted_run run;
    run.files = std::make_unique<setup_files>();
    run.scenario =
        config::parse_written_scenario(setup.scenario_yaml, "the coordinator's scenario");
    controller::resolve_strategy(run.scenario);
    // Cameras only look at the station: unless crowd partitions step here, no walker needs its
    // distance fields, which are most of a large station's loading time (the coordinator has
    // checked the layout).
    world::navigation_settings looked_at;
    looked_at.fields = setup.steps_crowd;
    looked_at.threads = st.field_threads;
    // The coordinator has just stored the fields in this machine's cache, if it shares it.
    looked_at.field_cache = world::field_cache::default_dir_or_none();
    auto station =
        world::station::load(run.files->write("layout.yaml", setup.layout_text), looked_at);
    if (setup.steps_crowd)
      spdlog::info("worker {}: distance fields {}", st.name,
                   station->fields_from_cache() ? "read from the field cache" : "computed");
    if (const auto& problem = station->field_cache_problem(); !problem.empty())
      spdlog::warn("worker {}: the distance fields were not kept for the next run: {}", st.name,
                   problem);
    vision::sensor_model model;
    if (!setup.sensor_model_text.empty())
      model = vision::load_sensor_model(
          run.files->write("sensor_model.yaml", setup.sensor_model_text).string());
    run.log = std::make_shared<eval::observation_log>(setup.with_visible);
    run.stream_log = setup.stream_log;
    run.steps_crowd = setup.steps_crowd;
    run.picks = std::make_shared<pick_outbox>();
    run.world = make_camera_world(run.scenario, station, std::move(model),
                                  std::max<std::size_t>(1, st.render_threads), run.log);
    if (setup.with_poses) run.world->poses = std::make_shared<camera_pose_board>();
    if (setup.video.on()) {
      run.video = setup.video;
      run.video_renderers =
          spawn_render_pool(self->system(), station, std::max<std::size_t>(1, st.render_threads))
              .front;
      run.spawned.push_back(run.video_renderers);
      const auto renderers = std::max<std::size_t>(1, st.render_threads);
      spdlog::info("worker {}: rendering its cameras' video tiles ({}x{} pixels, {} renderer{})",
                   st.name, setup.video.width_px, setup.video.height_px, renderers,
                   renderers == 1 ? "" : "s");
    }
    auto observer = std::make_shared<run_observer>(
        run.log, nullptr, [picks = run.picks](const eval::task_origin& o) { picks->add(o); });
    if (setup.live) {
      // The operator's orders arrive with the world's snapshot, before the cameras' turns.
      run.world->operators = std::make_shared<operator_board>();
      run.display = std::make_shared<display_relay>(std::move(observer));
      run.world->observer = run.display;
    } else {
      run.world->observer = std::move(observer);
    }
    auto model_of_links = make_link_model(run.scenario);
    std::vector<caf::actor> links;
    for (const auto& l : setup.links) {
      links.push_back(spawn_link(self->system(), run.scenario, model_of_links, l.index, l.a, l.b));
      run.spawned.push_back(links.back());
    }
    if (setup.coordinator) self->monitor(setup.coordinator);
    run.coordinator = setup.coordinator;
    st.run = std::move(run);
    spdlog::info("worker {}: hosting '{}' ({} links{})", st.name, st.run->scenario.name,
                 links.size(), st.run->display ? ", live: the operator's orders come here" : "");
    return links;
  } catch (const std::exception& e) {
    return refuse(self, fmt::format("worker {} cannot host the run: {}", st.name, e.what()));
  }
}

const config::camera_settings* camera_of(const hosted_run& run, int id) {
  for (const auto& c : run.scenario.cameras)
    if (c.id == id) return &c;
  return nullptr;
}

caf::error no_such_camera(host_actor* self, int id) {
  return refuse(self,
                fmt::format("worker {}: the scenario has no camera {}", self->state.name, id));
}

// Renders a tile of the video for the coordinator (actors/video_tiles.hpp): its camera at the
// pose asked, looking at the snapshot on this worker's board.
caf::result<video_tile> render_tile(host_actor* self, const video_tile_request& tile) {
  auto& st = self->state;
  if (!st.run || !st.run->video_renderers)
    return refuse(self, fmt::format("worker {} was not set up to render the video", st.name));
  const auto* camera = camera_of(*st.run, tile.camera);
  if (!camera) return no_such_camera(self, tile.camera);
  render_request request;
  try {
    std::optional<vision::imaging_model> imaging;
    if (tile.imaging)
      imaging = video_imaging_model(*camera, st.run->video, st.run->scenario.run.seed);
    request = from_tile_request(tile, *camera, st.run->video, st.run->last, std::move(imaging));
  } catch (const std::invalid_argument& e) {
    return refuse(self, fmt::format("worker {}: {}", st.name, e.what()));
  }
  auto promise = self->make_response_promise<video_tile>();
  self->request(st.run->video_renderers, caf::infinite, render_atom_v, std::move(request))
      .then(
          [self, promise](render_result& result) mutable {
            try {
              auto tile = to_tile(result);
              if (auto& run = self->state.run) {
                ++run->tiles_sent;
                run->tile_bytes_sent += tile.bytes.size();
              }
              promise.deliver(std::move(tile));
            } catch (const std::invalid_argument& e) {
              promise.deliver(caf::make_error(caf::sec::runtime_error, e.what()));
            }
          },
          [promise](caf::error& err) mutable { promise.deliver(std::move(err)); });
  return promise;
}

// Ticked through this host, as its cameras are; watched, so one that dies is not waited for.
void host_participant(host_actor* self, std::uint64_t id, const caf::actor& actor) {
  auto& run = *self->state.run;
  run.spawned.push_back(actor);
  run.participants[id] = actor;
  run.participant_of[actor.address()] = id;
  self->monitor(actor);
}

caf::result<caf::actor> spawn_partition(host_actor* self, partition_placement& placed) {
  auto& st = self->state;
  if (!st.run)
    return refuse(self, fmt::format("worker {} has no run to step a crowd partition in", st.name));
  if (!st.run->steps_crowd)
    return refuse(self, fmt::format("worker {} was not set up to step the crowd (no distance "
                                    "fields loaded)",
                                    st.name));
  crowd_partition_setup setup;
  setup.index = placed.index;
  setup.station = st.run->world->station;
  setup.bounds = {placed.min_x_m, placed.max_x_m};
  setup.behaviour = world::crowd_settings::from(st.run->scenario).behaviour;
  setup.pedestrians = std::move(placed.pedestrians);
  setup.board = st.run->world->board;
  setup.checkpoints = placed.checkpoints;
  spdlog::info("worker {}: stepping crowd partition {} ({} pedestrians at the start)", st.name,
               placed.index, setup.pedestrians.size());
  auto partition = spawn_crowd_partition(self->system(), std::move(setup));
  host_participant(self, participant_ids::crowd_partition(placed.index), partition);
  return partition;
}

caf::result<std::vector<caf::actor>> spawn_cameras(host_actor* self,
                                                   std::vector<camera_placement>& cameras) {
  auto& st = self->state;
  if (!st.run)
    return refuse(self, fmt::format("worker {} has no run to spawn cameras in", st.name));
  std::vector<caf::actor> out;
  for (auto& c : cameras) {
    const auto* camera = camera_of(*st.run, c.camera);
    if (!camera) return no_such_camera(self, c.camera);
    link_directory links;
    for (auto& l : c.links) links[l.neighbour] = attached_link{l.participant, std::move(l.handle)};
    auto node = spawn_camera_node(self->system(), st.run->scenario, *camera, std::move(links),
                                  st.run->world);
    host_participant(self, participant_ids::camera(c.camera), node);
    out.push_back(std::move(node));
  }
  return out;
}

// What its cameras did since it was last asked (worker_gather).
worker_gather take_gather(hosted_run& run) {
  worker_gather out;
  out.picks = run.picks->take();
  if (const auto& poses = run.world->poses)
    for (const auto& [camera, e] : poses->latest()) out.poses.push_back({camera, e.tick, e.pose});
  if (run.stream_log) out.log = run.log->take_recorded();
  if (run.display) out.display = run.display->take();
  return out;
}

// Answers the clock once every camera of the batch has acknowledged (or died). The world's
// phase comes just before the network's, where the world coordinator needs what the cameras
// did: nothing here acts in between, so the answer carries it, and the coordinator need not
// ask (`gather_atom`), a round trip less a tick.
void answer_batch(host_actor* self) {
  auto& run = *self->state.run;
  auto& batch = run.batch;
  if (!batch.waiting.empty() || !batch.clock) return;
  if (batch.phase == static_cast<std::uint8_t>(phase::world))
    self->send(batch.clock, std::move(batch.acks), take_gather(run));
  else
    self->send(batch.clock, std::move(batch.acks));
  batch.acks.clear();
  batch.clock = caf::actor{};
}

void tick_batch_of(host_actor* self, std::int64_t tick, std::uint8_t phase,
                   const std::vector<batched_tick>& due) {
  auto& run = *self->state.run;
  auto& batch = run.batch;
  batch.clock = caf::actor_cast<caf::actor>(self->current_sender());
  batch.phase = phase;
  for (const auto& d : due) {
    auto it = run.participants.find(d.participant);
    if (it == run.participants.end()) continue;  // gone: the clock watches it too
    batch.waiting.insert(d.participant);
    self->send(it->second, tick_atom_v, tick, phase, d.relayed);
  }
  answer_batch(self);
}

void on_down(host_actor* self, const caf::down_msg& msg) {
  auto& st = self->state;
  if (!st.run) return;
  // A coordinator that goes away leaves nothing behind: what it spawned here ends with it.
  if (msg.source == st.run->coordinator.address()) {
    end_run(self);
    return;
  }
  auto it = st.run->participant_of.find(msg.source);
  if (it == st.run->participant_of.end()) return;
  const auto id = it->second;
  st.run->participant_of.erase(it);
  // A camera crashed and spawned again in one turn: the old one's end may come after the new
  // one took its id.
  auto current = st.run->participants.find(id);
  if (current == st.run->participants.end() || current->second.address() != msg.source) return;
  st.run->participants.erase(current);
  st.run->batch.waiting.erase(id);
  answer_batch(self);
}

caf::behavior worker_host(host_actor* self, std::string name, std::size_t render_threads,
                          unsigned field_threads) {
  self->state.name = std::move(name);
  self->state.render_threads = render_threads;
  self->state.field_threads = field_threads;
  self->set_down_handler([self](caf::down_msg& msg) { on_down(self, msg); });
  // A host that is ended takes what it hosts with it, for the same reason: a coordinator sees
  // the cameras and links of a host that goes as it sees those of a worker that goes.
  self->set_exit_handler([self](caf::exit_msg& msg) {
    if (auto& run = self->state.run)
      for (auto& a : run->spawned) self->send_exit(a, msg.reason);
    self->state.run.reset();
    self->quit(msg.reason);
  });
  return {
      [self](tick_atom, std::int64_t tick, std::uint8_t phase, std::vector<batched_tick>& due) {
        if (self->state.run) tick_batch_of(self, tick, phase, due);
      },
      [self](tick_ack& ack) {
        auto& st = self->state;
        if (!st.run) return;
        auto& batch = st.run->batch;
        if (batch.waiting.erase(ack.participant) == 0) return;  // not of this phase: stray
        batch.acks.push_back(std::move(ack));
        answer_batch(self);
      },
      [self](worker_hello_atom,
             const std::string& version) -> caf::result<std::string, std::string> {
        if (version != argus_version())
          return refuse(self, fmt::format("worker {} runs Argus {} and the coordinator Argus {}",
                                          self->state.name, argus_version(), version));
        return {std::string(argus_version()), self->state.name};
      },
      [self](listening_atom, std::string& name) { self->state.name = std::move(name); },
      [self](worker_setup_atom, worker_setup& setup) { return set_up(self, setup); },
      [self](spawn_cameras_atom, std::vector<camera_placement>& cameras) {
        return spawn_cameras(self, cameras);
      },
      [self](spawn_partition_atom, partition_placement& placed) {
        return spawn_partition(self, placed);
      },
      [self](gather_atom) -> worker_gather {
        auto& st = self->state;
        if (!st.run) return {};
        return take_gather(*st.run);
      },
      [self](display_watch_atom, const display_watch& watch) {
        auto& st = self->state;
        if (st.run && st.run->display) st.run->display->watch(watch.cameras);
      },
      [self](operator_orders_atom, std::vector<operator_order>& orders) {
        auto& st = self->state;
        if (!st.run || !st.run->world->operators) return;
        for (auto& order : orders) st.run->world->operators->publish(std::move(order));
      },
      [self](board_atom, const serialized_delta& delta,
             const std::vector<eval::task_origin>& picks) -> caf::result<done_atom> {
        auto& st = self->state;
        if (!st.run) return done_atom_v;
        for (const auto& o : picks) st.run->log->add_origin_if_new(o);
        try {
          st.run->last =
              apply_delta(*st.run->world->station, st.run->last.get(), deserialize(delta));
        } catch (const std::invalid_argument& e) {
          return refuse(self, fmt::format("worker {}: {}", st.name, e.what()));
        }
        st.run->world->board->publish(st.run->last);
        return done_atom_v;
      },
      [self](video_tile_atom, const video_tile_request& tile) { return render_tile(self, tile); },
      [self](take_display_atom) -> live_display {
        auto& st = self->state;
        if (!st.run || !st.run->display) return {};
        return st.run->display->take();
      },
      [self](take_log_atom) -> eval::observation_log::contents {
        auto& st = self->state;
        if (!st.run) return {};
        return st.run->log->take();
      },
      [self](release_atom) {
        end_run(self);
        return done_atom_v;
      },
  };
}

}  // namespace

caf::actor spawn_worker_host(caf::actor_system& system, std::string name,
                             std::size_t render_threads, unsigned field_threads) {
  return system.spawn(worker_host, std::move(name), render_threads, field_threads);
}

}  // namespace argus::actors
