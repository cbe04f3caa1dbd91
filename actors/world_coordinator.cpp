#include "actors/world_coordinator.hpp"

#include <algorithm>
#include <future>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <thread>
#include <utility>

#include "actors/crowd_partition.hpp"
#include "actors/ordered_inbox.hpp"
#include "actors/participant_ids.hpp"
#include "actors/partition_shadow.hpp"
#include "actors/tick_context.hpp"
#include "actors/trajectory_recorder.hpp"
#include "actors/type_ids.hpp"
#include "actors/wire_world.hpp"
#include "fmt/format.h"
#include "spdlog/spdlog.h"

namespace argus::actors {
namespace {

struct coordinator_setup {
  std::shared_ptr<const world::station> station;
  std::vector<world::partition_bounds> bounds;
  world::spawner spawner;
  double tick_s = 1.0 / 15.0;
  std::shared_ptr<const world::snapshot> initial;
  std::int64_t end_tick = 0;
  /// Null for none; shared only to pass it into the actor.
  std::shared_ptr<trajectory_file> trajectories;
  std::vector<caf::actor> partitions;
  /// By partition: whether it steps on a worker (it keeps its own pedestrians there).
  std::vector<bool> on_worker;
  std::vector<std::pair<caf::actor, std::uint64_t>> snapshot_observers;
  std::shared_ptr<snapshot_board> board;
  std::vector<caf::actor> remote_boards;
  std::function<void(const std::vector<eval::task_origin>&)> picks_gathered;
  std::function<void(const std::vector<pose_record>&)> poses_gathered;
  std::function<void(eval::observation_log::contents)> log_gathered;
  worker_loss on_worker_loss = worker_loss::end_run;
  std::shared_ptr<const operator_board> operators;
  std::function<void(live_display)> display_gathered;
  world::behaviour_settings behaviour;
  /// By partition: the worker that steps it (its host's address and name), for a partition on
  /// a worker.
  std::vector<caf::actor_addr> host_of;
  std::vector<std::string> host_name_of;
  /// The shadows of the workers' partitions at the start (crash-nodes), moved into the state.
  std::map<std::size_t, partition_shadow> shadows;
  std::function<std::vector<int>()> watched_cameras;
  std::size_t adopted_threads = 0;
};

// A distributed tick in progress: the workers whose gathers are still awaited.
struct remote_exchange {
  enum class stage : std::uint8_t { idle, gathering };
  stage now = stage::idle;
  std::optional<tick_context> ctx;
  caf::actor clock;
  std::vector<std::pair<mail_stamp, partition_report>> due;
  std::vector<eval::task_origin> picks;
  // What the workers' cameras recorded since the last gather, by worker, added in the
  // workers' order once all have answered.
  std::map<std::size_t, std::vector<eval::observation_log::contents>> logs;
  std::set<caf::actor_addr> awaited;
};

struct world_coordinator_state {
  participant_info info;
  std::optional<coordinator_setup> setup;
  std::shared_ptr<const world::snapshot> current;
  /// The snapshot the workers' boards hold: the next one travels as changes to it.
  std::shared_ptr<const world::snapshot> published;
  ordered_inbox<partition_report> reports;
  std::uint64_t sent = 0;
  remote_exchange exchange;
  /// How many of the operator's orders have gone out to the workers.
  std::size_t orders_sent = 0;
  /// Under `--on-worker-loss crash-nodes`, by partition on a worker: what it takes to step it
  /// here if its worker is lost.
  std::map<std::size_t, partition_shadow> shadows;
  /// Partitions whose worker is gone, to be stepped here from the next step of the world on.
  std::set<std::size_t> lost_partitions;
  /// Partitions that step here since their worker was lost: their pedestrians for the next step.
  std::map<std::size_t, std::vector<world::pedestrian>> adopted;
  /// The cameras the workers were last told a page watches.
  std::vector<int> watched_sent;
  /// What each worker's cameras did, as its answers in phase world brought it (through the
  /// clock, `gather_atom`), since the world last took it, and the tick of the last.
  struct pushed_gathers {
    std::int64_t tick = -1;
    std::vector<worker_gather> gathers;
  };
  std::map<caf::actor_addr, pushed_gathers> pushed;
  /// `current` is stepped but its rows are not yet handed to `rows`: they go once the tick is
  /// acknowledged (`acknowledge`).
  bool unwritten = false;
  /// Writes trajectories.csv on a thread of its own (trajectory_recorder.hpp); null for none.
  caf::actor rows;
  /// Snapshots handed to `rows` and not yet written.
  std::size_t rows_in_flight = 0;
  /// An acknowledgement held back until `rows` catches up, and the clock it is for.
  std::optional<std::pair<caf::actor, tick_ack>> held_ack;
};

/// How many snapshots the rows' writer may fall behind (a disk slower than the run) before the
/// world holds back its acknowledgement, and so the clock, until it catches up: about 2 MB each
/// for 10,000 pedestrians.
constexpr std::size_t max_rows_in_flight = 8;

// The lean part of the world's events: entries, exits and completed goals.
void emit_events(tick_context& ctx, const world::snapshot& frame) {
  for (const auto& e : frame.events()) {
    switch (e.kind) {
      case world::event_kind::spawned:
        ctx.emit(events::pedestrian_moved{
            .entered = true, .pedestrian = e.pedestrian, .at = e.resource});
        break;
      case world::event_kind::left:
        ctx.emit(events::pedestrian_moved{
            .entered = false, .pedestrian = e.pedestrian, .at = e.resource});
        break;
      case world::event_kind::goal_completed:
        ctx.emit(events::goal_completed{.pedestrian = e.pedestrian,
                                        .goal = std::string(world::to_string(e.goal))});
        break;
      default:
        break;
    }
  }
}

// A partition on a worker reported only the states of those it kept, as changes to the
// snapshot it stepped from (`before`): here they stand in for whole pedestrians, whose states
// are all the merge reads.
partition_report report_of(partition_states states) {
  partition_report out;
  out.index = states.index;
  out.kept = std::move(states.kept);
  out.result.handed_over = std::move(states.handed_over);
  out.result.events = std::move(states.events);
  if (states.checkpoint) out.whole = std::move(states.whole);
  return out;
}

// The states the workers' partitions kept, read back from the snapshot they stepped from, all
// the reports in one pass over it (apply_subsets).
void read_kept(const std::vector<partition_report*>& reports, const world::snapshot& before) {
  std::vector<partition_report*> from_workers;
  std::vector<subset_delta> deltas;
  for (auto* report : reports) {
    if (!report->kept) continue;
    from_workers.push_back(report);
    deltas.push_back(std::move(*report->kept));
    report->kept.reset();
  }
  if (deltas.empty()) return;
  auto kept = apply_subsets(before, std::move(deltas));
  for (std::size_t r = 0; r < from_workers.size(); ++r) {
    auto& pedestrians = from_workers[r]->result.pedestrians;
    pedestrians.resize(kept[r].size());
    for (std::size_t k = 0; k < kept[r].size(); ++k) pedestrians[k].state = std::move(kept[r][k]);
  }
}

// The partitions of a lost worker step here from now on, from the pedestrians their shadows
// give back: those their worker held at the start of this tick.
void adopt_lost_partitions(caf::stateful_actor<world_coordinator_state>* self, tick_context& ctx) {
  auto& st = self->state;
  const auto& setup = *st.setup;
  for (auto i : st.lost_partitions) {
    auto shadow = st.shadows.find(i);
    if (shadow == st.shadows.end()) continue;
    const auto replayed = shadow->second.ticks_since_checkpoint();
    st.adopted[i] = shadow->second.replay(*setup.station, setup.bounds[i], setup.behaviour);
    spdlog::warn(
        "world: crowd partition {} steps here from tick {} on, its worker {} being lost ({} "
        "pedestrians, {} ticks stepped again from its last checkpoint)",
        i, ctx.tick(), setup.host_name_of[i], st.adopted[i].size(), replayed);
    ctx.emit(events::world_partition_adopted{
        .partition = i, .worker = setup.host_name_of[i], .replayed_ticks = replayed});
    st.shadows.erase(shadow);
  }
  st.lost_partitions.clear();
}

// A lost worker's partitions step side by side, as they did on their worker. Stepped one after
// another in this turn, they made every later tick wait on one core for the half of a large
// crowd that the worker had stepped. Each step reads only the last snapshot, so which thread
// steps which partition changes no result.
void step_adopted(const std::map<std::size_t, std::vector<world::pedestrian>>& adopted,
                  const world::station& where, const world::snapshot& previous,
                  const std::vector<world::partition_bounds>& bounds,
                  const world::behaviour_settings& behaviour, std::size_t threads_at_most,
                  std::vector<world::partition_result>& results) {
  if (adopted.empty()) return;
  std::vector<std::size_t> order;
  for (const auto& entry : adopted) order.push_back(entry.first);
  if (threads_at_most == 0) threads_at_most = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads = std::min(order.size(), threads_at_most);
  auto step_every = [&](std::size_t first) {
    for (std::size_t k = first; k < order.size(); k += threads) {
      const auto i = order[k];
      results[i] = world::partition_step(where, previous, adopted.at(i), bounds[i], behaviour);
    }
  };
  std::vector<std::future<void>> others;
  for (std::size_t t = 1; t < threads; ++t)
    others.push_back(std::async(std::launch::async, step_every, t));
  step_every(0);
  for (auto& other : others) other.get();
}

void step_world(caf::stateful_actor<world_coordinator_state>* self, tick_context& ctx,
                std::vector<std::pair<mail_stamp, partition_report>> due) {
  auto& st = self->state;
  auto& setup = *st.setup;
  const auto count = setup.bounds.size();
  adopt_lost_partitions(self, ctx);
  // Canonical order: by partition index, whatever order the reports arrived in.
  std::vector<world::partition_result> results(count);
  std::vector<bool> reported_by(count, false);
  std::vector<std::optional<std::vector<world::pedestrian>>> checkpoints(count);
  std::size_t reported = 0;
  std::vector<partition_report*> taken;
  for (auto& [stamp, report] : due) {
    // An adopted partition's last report, sent before its worker went, is stepped again here.
    if (report.index >= count || st.adopted.count(report.index) != 0) continue;
    taken.push_back(&report);
  }
  read_kept(taken, *st.current);
  for (auto* report : taken) {
    results[report->index] = std::move(report->result);
    checkpoints[report->index] = std::move(report->whole);
    reported_by[report->index] = true;
    ++reported;
  }
  step_adopted(st.adopted, *setup.station, *st.current, setup.bounds, setup.behaviour,
               setup.adopted_threads, results);
  reported += st.adopted.size();
  const auto previous = st.current;
  if (reported != count)
    ctx.emit(events::world_partitions_missing{.reported = reported, .partitions = count});
  const auto world_tick = st.current->tick() + 1;
  std::vector<world::event> spawn_events;
  auto states = world::gather_states(results);
  auto spawned = setup.spawner.spawn(*setup.station, states, world_tick, spawn_events);
  st.current =
      world::merge(*setup.station, world_tick,
                   std::chrono::duration<double>{static_cast<double>(world_tick) * setup.tick_s},
                   std::move(states), results, spawned, std::move(spawn_events));
  st.unwritten = true;
  if (setup.board) setup.board->publish(st.current);
  emit_events(ctx, *st.current);
  // Redistribute in world::crowd::step's order: own, handed over, newcomers. A partition on
  // a worker kept its own: it is sent the others only.
  std::vector<std::vector<world::pedestrian>> owned(count);
  for (std::size_t i = 0; i < count; ++i)
    if (!setup.on_worker[i] || st.adopted.count(i) != 0)
      owned[i] = std::move(results[i].pedestrians);
  for (auto& r : results)
    for (auto& p : r.handed_over)
      owned[world::owner_of(setup.bounds, p.state.position)].push_back(std::move(p));
  for (auto& p : spawned)
    owned[world::owner_of(setup.bounds, p.state.position)].push_back(std::move(p));
  for (std::size_t i = 0; i < count; ++i) {
    if (auto adopted = st.adopted.find(i); adopted != st.adopted.end()) {
      adopted->second = std::move(owned[i]);
      continue;
    }
    if (auto shadow = st.shadows.find(i); shadow != st.shadows.end() && reported_by[i])
      shadow->second.stepped(previous, checkpoints[i] ? &*checkpoints[i] : nullptr, owned[i]);
    mail_stamp stamp{ctx.tick(), static_cast<std::uint8_t>(st.info.tick_phase), st.info.id,
                     st.sent++};
    if (setup.on_worker[i])
      self->send(setup.partitions[i], world_update_atom_v, stamp,
                 partition_arrivals{std::move(owned[i])});
    else
      self->send(setup.partitions[i], world_update_atom_v, stamp,
                 world_update{st.current, std::move(owned[i])});
    ctx.sent_mail_to(participant_ids::crowd_partition(i));
  }
  for (const auto& [observer, id] : setup.snapshot_observers) {
    mail_stamp stamp{ctx.tick(), static_cast<std::uint8_t>(st.info.tick_phase), st.info.id,
                     st.sent++};
    self->send(observer, world_snapshot_atom_v, stamp, st.current);
    ctx.sent_mail_to(id);
  }
}

using coordinator_actor = caf::stateful_actor<world_coordinator_state>;

void worker_answered(coordinator_actor* self, const caf::actor_addr& board);

// A worker is gone (`--on-worker-loss crash-nodes`): the world goes on without it, and the
// tick in progress stops waiting for its answer. The clock takes its cameras down.
void lose_board(coordinator_actor* self, const caf::actor_addr& board) {
  auto& boards = self->state.setup->remote_boards;
  auto it = std::find_if(boards.begin(), boards.end(),
                         [&](const caf::actor& b) { return b.address() == board; });
  if (it == boards.end()) return;
  boards.erase(it);
  self->state.pushed.erase(board);
  const auto& hosts = self->state.setup->host_of;
  for (std::size_t i = 0; i < hosts.size(); ++i)
    if (hosts[i] == board && self->state.shadows.count(i) != 0)
      self->state.lost_partitions.insert(i);
  spdlog::warn("world: a worker is gone; {} left to share the world with", boards.size());
  worker_answered(self, board);
}

// A worker's failed answer. Unless the run survives lost workers, a worker that is gone ends
// the run through the clock (it monitors the worker's cameras), so this tick is never
// acknowledged. A worker that answered with an error instead (a snapshot it could not
// rebuild) ends the run: without the world the clock cannot go on.
void worker_failed(coordinator_actor* self, const caf::actor_addr& board, const caf::error& err) {
  if (err != caf::sec::runtime_error &&
      self->state.setup->on_worker_loss == worker_loss::crash_nodes) {
    lose_board(self, board);
    return;
  }
  spdlog::error("world: a worker did not answer: {}", self->system().render(err));
  if (err == caf::sec::runtime_error) self->quit(err);
}

void step_and_publish(coordinator_actor* self);

// Acknowledges the tick, then hands the snapshot it stepped to the rows' writer. Nothing in
// the run reads the rows, so the clock's next phase (the cameras, here or on the workers) need
// not wait for their text: about 3 ms a tick for the large station's 10,000 pedestrians.
void acknowledge(coordinator_actor* self, caf::actor clock, tick_ack ack) {
  auto& st = self->state;
  if (st.unwritten && st.rows_in_flight >= max_rows_in_flight) {
    st.held_ack.emplace(std::move(clock), std::move(ack));
    return;
  }
  self->send(clock, std::move(ack));
  if (!st.unwritten) return;
  st.unwritten = false;
  if (!st.rows) return;
  ++st.rows_in_flight;
  self->send(st.rows, world_snapshot_atom_v, st.current);
}

void publish_to_workers(coordinator_actor* self) {
  auto& st = self->state;
  auto& ex = st.exchange;
  auto delta = delta_between(st.published.get(), *st.current);
  const auto bytes = serialize(delta);
  st.published = st.current;
  // Sent before the snapshot by the same actor, so each worker has them before it reads it.
  if (st.setup->operators)
    if (auto orders = st.setup->operators->take_all_new(st.orders_sent); !orders.empty())
      for (const auto& board : st.setup->remote_boards)
        self->send(board, operator_orders_atom_v, orders);
  if (st.setup->watched_cameras)
    if (auto watched = st.setup->watched_cameras(); watched != st.watched_sent) {
      for (const auto& board : st.setup->remote_boards)
        self->send(board, display_watch_atom_v, display_watch{watched});
      st.watched_sent = std::move(watched);
    }
  // The tick is acknowledged without waiting for the workers' answers: each worker's host
  // reads the delta before anything the clock sends it once it has the acknowledgement (its
  // batch of the next phase), because CAF delivers one connection's messages in the order they
  // were sent. The workers rebuild while the acknowledgement and the clock's next batch travel:
  // a round trip less a tick. Only an answer that is a failure is acted on.
  for (const auto& board : st.setup->remote_boards)
    self->request(board, caf::infinite, board_atom_v, bytes, ex.picks)
        .then([](done_atom) {},
              [self, addr = board.address()](caf::error& err) { worker_failed(self, addr, err); });
  ex.now = remote_exchange::stage::idle;
  ex.picks.clear();
  acknowledge(self, std::exchange(ex.clock, caf::actor{}), std::move(*ex.ctx).finish());
  ex.ctx.reset();
}

// What worker `w`'s cameras did, from its answer in phase world or to `gather_atom`.
void absorb_gather(coordinator_actor* self, std::size_t w, worker_gather gathered) {
  auto& st = self->state;
  auto& ex = st.exchange;
  ex.picks.insert(ex.picks.end(), gathered.picks.begin(), gathered.picks.end());
  // Each camera is on one worker: the order of the workers' answers cannot matter.
  if (st.setup->poses_gathered) st.setup->poses_gathered(gathered.poses);
  if (st.setup->log_gathered) ex.logs[w].push_back(std::move(gathered.log));
  if (st.setup->display_gathered) st.setup->display_gathered(std::move(gathered.display));
}

// A worker whose answer in this tick's phase world brought what its cameras did is not asked
// again: nothing on it acts between that phase and this one. One that stepped nothing in
// phase world (no crowd partition of its own) is asked.
void gather_picks(coordinator_actor* self, tick_context ctx, caf::actor clock,
                  std::vector<std::pair<mail_stamp, partition_report>> due) {
  auto& st = self->state;
  auto& ex = st.exchange;
  ex.now = remote_exchange::stage::gathering;
  ex.ctx.emplace(std::move(ctx));
  ex.clock = std::move(clock);
  ex.due = std::move(due);
  const auto boards = st.setup->remote_boards;
  std::vector<std::size_t> ask;
  for (std::size_t w = 0; w < boards.size(); ++w) {
    bool answered = false;
    if (auto it = st.pushed.find(boards[w].address()); it != st.pushed.end()) {
      answered = it->second.tick == ex.ctx->tick();
      for (auto& gathered : it->second.gathers) absorb_gather(self, w, std::move(gathered));
      st.pushed.erase(it);
    }
    if (answered) continue;
    ask.push_back(w);
    ex.awaited.insert(boards[w].address());
  }
  for (auto w : ask)
    self->request(boards[w], caf::infinite, gather_atom_v)
        .then(
            [self, w, addr = boards[w].address()](worker_gather& gathered) {
              absorb_gather(self, w, std::move(gathered));
              worker_answered(self, addr);
            },
            [self, addr = boards[w].address()](caf::error& err) {
              worker_failed(self, addr, err);
            });
  if (ex.awaited.empty()) worker_answered(self, caf::actor_addr{});
}

// Every worker still there has answered the gather: the world steps and is published.
void step_and_publish(coordinator_actor* self) {
  auto& st = self->state;
  auto& ex = st.exchange;
  // Whatever order the workers answered in.
  std::sort(ex.picks.begin(), ex.picks.end(),
            [](const auto& a, const auto& b) { return a.task < b.task; });
  if (st.setup->picks_gathered) st.setup->picks_gathered(ex.picks);
  for (auto& [w, shares] : ex.logs)
    for (auto& share : shares) st.setup->log_gathered(std::move(share));
  ex.logs.clear();
  step_world(self, *ex.ctx, std::move(ex.due));
  publish_to_workers(self);
}

// `board` answered, or is gone: once none is awaited, the exchange moves on.
void worker_answered(coordinator_actor* self, const caf::actor_addr& board) {
  auto& ex = self->state.exchange;
  if (ex.awaited.erase(board) == 0 && board) return;  // not awaited (answered, or lost, before)
  if (!ex.awaited.empty()) return;
  switch (ex.now) {
    case remote_exchange::stage::idle:
      return;
    case remote_exchange::stage::gathering:
      step_and_publish(self);
      return;
  }
}

caf::behavior world_coordinator(coordinator_actor* self, coordinator_setup setup) {
  auto& st = self->state;
  st.info = world_coordinator_participant();
  st.current = setup.initial;
  st.published = setup.initial;  // run_scenario shares it with the workers before the first tick
  st.setup.emplace(std::move(setup));
  st.shadows = std::move(st.setup->shadows);
  // A run that ends early (a lost worker, a strategy that raised) still leaves whole files:
  // the rows' writer, linked, writes every tick it was handed and gives them their names.
  if (st.setup->trajectories)
    st.rows =
        spawn_trajectory_recorder(self, std::move(st.setup->trajectories), st.setup->end_tick);
  self->set_exit_handler([self](caf::exit_msg& msg) { self->quit(msg.reason); });
  // Under `--on-worker-loss crash-nodes` a worker that goes is noticed here too: an answer it
  // owed may never come.
  if (st.setup->on_worker_loss == worker_loss::crash_nodes) {
    for (const auto& board : st.setup->remote_boards) self->monitor(board);
    self->set_down_handler([self](caf::down_msg& msg) { lose_board(self, msg.source); });
  }
  return {
      [self](world_report_atom, const mail_stamp& stamp, partition_report& report) {
        self->state.reports.put(stamp, std::move(report));
      },
      [self](world_report_atom, const mail_stamp& stamp, partition_states& states) {
        self->state.reports.put(stamp, report_of(std::move(states)));
      },
      [self](gather_atom, const caf::actor_addr& worker, std::int64_t tick,
             worker_gather& gathered) {
        auto& pushed = self->state.pushed[worker];
        pushed.tick = tick;
        pushed.gathers.push_back(std::move(gathered));
      },
      [self](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        auto due = st.reports.take_due(tick, p);
        auto clock = caf::actor_cast<caf::actor>(self->current_sender());
        // While partitions step on workers that may be lost, or here for lost ones, the world
        // steps every tick even if no report came: all of them may have gone with their worker.
        const bool any_may_go = !st.shadows.empty() || !st.adopted.empty();
        if (any_may_go) ctx.wake_at(tick + 1);
        if ((!due.empty() || any_may_go) && !st.setup->remote_boards.empty()) {
          gather_picks(self, std::move(ctx), std::move(clock), std::move(due));
          return;
        }
        if (!due.empty() || any_may_go) step_world(self, ctx, std::move(due));
        acknowledge(self, std::move(clock), std::move(ctx).finish());
      },
      [self](recorded_atom, std::int64_t) {
        auto& st = self->state;
        if (st.rows_in_flight > 0) --st.rows_in_flight;
        if (!st.held_ack) return;
        auto [clock, ack] = std::move(*st.held_ack);
        st.held_ack.reset();
        acknowledge(self, std::move(clock), std::move(ack));
      },
  };
}

}  // namespace

participant_info world_coordinator_participant() {
  participant_info info;
  info.id = participant_ids::world_coordinator;
  info.name = "world";
  info.tick_phase = phase::network;
  info.mode = wake_mode::on_demand;
  return info;
}

world_actors spawn_world(caf::actor_system& system, world_run_settings settings) {
  const auto& cs = settings.crowd;
  // The same checks and initial crowd as world::crowd's constructor.
  if (cs.behaviour.tick_s <= 0.0 || cs.behaviour.tick_s > 0.25)
    throw std::invalid_argument("world: tick must be in (0, 0.25] s");
  world::spawner spawner(cs.spawning(*settings.station));
  auto bounds = world::vertical_strips(*settings.station, cs.partitions);
  std::vector<world::event> events;
  std::vector<world::pedestrian> initial;
  if (cs.prefill) initial = spawner.populate(*settings.station, 0, events);
  std::vector<std::vector<world::pedestrian>> owned(bounds.size());
  std::vector<world::pedestrian_state> states;
  for (auto& p : initial) {
    states.push_back(p.state);
    owned[world::owner_of(bounds, p.state.position)].push_back(std::move(p));
  }
  auto snapshot0 = std::make_shared<const world::snapshot>(*settings.station, 0,
                                                           std::chrono::duration<double>{0.0},
                                                           std::move(states), std::move(events));

  auto trajectories = open_trajectories(settings.trajectories);
  write_trajectories(trajectories, *snapshot0, settings.end_tick);
  if (settings.board) settings.board->publish(snapshot0);

  world_actors out;
  const auto count = bounds.size();
  std::vector<caf::actor> partitions(count);
  std::vector<bool> on_worker(count, false);
  std::vector<participant_info> infos;
  for (std::size_t i = 0; i < count; ++i) {
    infos.push_back(crowd_partition_participant(i));
    if (i < settings.partition_hosts.size() && settings.partition_hosts[i].host) {
      on_worker[i] = true;
      infos[i].host = settings.partition_hosts[i].name;
    }
  }
  // Under crash-nodes a worker's partition sends checkpoints, and is shadowed here from its
  // first pedestrians on.
  const bool checkpoints = settings.on_worker_loss == worker_loss::crash_nodes;
  std::map<std::size_t, partition_shadow> shadows;
  std::vector<caf::actor_addr> host_of(count);
  std::vector<std::string> host_name_of(count);
  // The workers' partitions first: a worker that refuses leaves nothing spawned here.
  {
    caf::scoped_actor self{system};
    for (std::size_t i = 0; i < count; ++i) {
      if (!on_worker[i]) continue;
      const auto& where = settings.partition_hosts[i];
      std::string failure;
      // As long as a worker may take to set up (remote_network.hpp, worker_setup_timeout).
      self->request(where.host, std::chrono::seconds(30), spawn_partition_atom_v,
                    partition_placement{i, bounds[i].min_x_m, bounds[i].max_x_m,
                                        checkpoints ? owned[i] : std::move(owned[i]), checkpoints})
          .receive([&](caf::actor& spawned) { partitions[i] = std::move(spawned); },
                   [&](caf::error& err) {
                     failure = err == caf::sec::request_timeout ? "no answer within 30 s"
                                                                : system.render(err);
                   });
      if (!failure.empty())
        throw std::runtime_error(
            fmt::format("worker {} (crowd partition {}): {}", where.name, i, failure));
      host_of[i] = where.host.address();
      host_name_of[i] = where.name;
      if (checkpoints) shadows.emplace(i, partition_shadow(std::move(owned[i])));
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (on_worker[i]) continue;
    crowd_partition_setup ps;
    ps.index = i;
    ps.station = settings.station;
    ps.bounds = bounds[i];
    ps.behaviour = cs.behaviour;
    ps.initial = snapshot0;
    ps.pedestrians = std::move(owned[i]);
    partitions[i] = spawn_crowd_partition(system, std::move(ps));
  }
  auto coordinator =
      system.spawn(world_coordinator, coordinator_setup{settings.station,
                                                        bounds,
                                                        std::move(spawner),
                                                        cs.behaviour.tick_s,
                                                        snapshot0,
                                                        settings.end_tick,
                                                        std::move(trajectories),
                                                        partitions,
                                                        on_worker,
                                                        std::move(settings.snapshot_observers),
                                                        settings.board,
                                                        std::move(settings.remote_boards),
                                                        std::move(settings.picks_gathered),
                                                        std::move(settings.poses_gathered),
                                                        std::move(settings.log_gathered),
                                                        settings.on_worker_loss,
                                                        std::move(settings.operators),
                                                        std::move(settings.display_gathered),
                                                        cs.behaviour,
                                                        std::move(host_of),
                                                        std::move(host_name_of),
                                                        std::move(shadows),
                                                        std::move(settings.watched_cameras),
                                                        settings.adopted_threads});
  for (std::size_t i = 0; i < partitions.size(); ++i) {
    caf::anon_send(partitions[i], world_attach_atom_v, coordinator);
    out.participants.emplace_back(partitions[i], infos[i]);
  }
  out.participants.emplace_back(coordinator, world_coordinator_participant());
  return out;
}

}  // namespace argus::actors
