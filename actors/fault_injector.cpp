#include "actors/fault_injector.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string_view>
#include <vector>

#include "actors/link_command.hpp"
#include "actors/ordered_inbox.hpp"
#include "actors/participant_ids.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "config/derive_seed.hpp"
#include "config/enum_names.hpp"
#include "config/ticks.hpp"
#include "fmt/format.h"
#include "fmt/ranges.h"
#include "spdlog/spdlog.h"

namespace argus::actors {
namespace {

struct planned {
  std::int64_t tick = 0;
  std::size_t fault = 0;  // index into scenario.faults
  bool recovery = false;  // the second half of a crash_and_recover
};

struct injector_state {
  participant_info info;
  config::scenario scenario;
  caf::actor clock;
  network_directory net;
  std::vector<planned> plan;  // by tick, then file order
  std::size_t next = 0;
  std::mt19937_64 rng;
  double failure_per_tick = 0.0;
  std::uint64_t mail_seq = 0;
  // This turn's commands to links, sent once the cameras crashed in it have ended: a dying
  // camera hands its links what it had sent (actors/link_outbox.hpp), and a link must read
  // that before any command of the turn, whatever the threads do. The ack is held until every
  // link has answered (its effects — hand-overs, retractions — then sit in the nodes'
  // mailboxes before their turn).
  std::set<caf::actor_addr> dying;
  std::vector<std::pair<caf::actor, link_command>> commands;
  std::size_t answers_pending = 0;
  std::int64_t tick = 0;
  std::optional<tick_ack> held_ack;
  std::shared_ptr<live::session> live;
  // A distributed run's cameras that recover on their worker, whose handles are still to come:
  // their attachments wait in `commands`, and no command goes out before every handle is in.
  // True: crashed again in the same turn, to be carried out once it exists.
  std::map<int, bool> spawning;
  // Workers lost since the last turn (`--on-worker-loss crash-nodes`), and the cameras they took.
  std::vector<lost_worker> lost;
  std::set<int> lost_cameras;
};

using injector = caf::stateful_actor<injector_state>;

void tell_links(injector* self, int camera, const link_command& cmd) {
  auto& st = self->state;
  auto it = st.net.links.find(camera);
  if (it == st.net.links.end()) return;
  for (const auto& [neighbour, link] : it->second) st.commands.emplace_back(link.handle, cmd);
}

void tell_link(injector* self, int a, int b, const link_command& cmd) {
  auto& st = self->state;
  auto it = st.net.links.find(a);
  if (it == st.net.links.end()) return;
  auto link = it->second.find(b);
  if (link == it->second.end()) return;
  st.commands.emplace_back(link->second.handle, cmd);
}

// Acknowledges the turn once no camera of it is still dying and every link has answered.
void ack_when_done(injector* self) {
  auto& st = self->state;
  if (!st.dying.empty() || !st.spawning.empty() || st.answers_pending > 0 || !st.held_ack) return;
  self->send(st.clock, std::move(*st.held_ack));
  st.held_ack.reset();
}

// Sends the turn's link commands in the order they were made, once the crashed are gone.
void send_commands(injector* self) {
  auto& st = self->state;
  if (!st.dying.empty() || !st.spawning.empty()) return;
  for (auto& [link, cmd] : st.commands) {
    mail_stamp stamp{st.tick, static_cast<std::uint8_t>(phase::faults), st.info.id, st.mail_seq++};
    ++st.answers_pending;
    auto answered = [self] {
      --self->state.answers_pending;
      ack_when_done(self);
    };
    self->request(link, caf::infinite, link_cmd_atom_v, stamp, std::move(cmd))
        .then([answered](done_atom) { answered(); }, [answered](caf::error&) { answered(); });
  }
  st.commands.clear();
}

// Retires the camera at the clock and ends its actor.
void kill_camera(injector* self, int camera, caf::actor& handle) {
  auto& st = self->state;
  // The retire reaches the clock before this actor's ack: the camera leaves the barrier at a
  // deterministic point, and its death is not reported as unexpected.
  self->send(st.clock, retire_atom_v, participant_ids::camera(camera));
  self->monitor(handle);
  st.dying.insert(handle.address());
  self->send_exit(handle, crash_reason());
  handle = caf::actor{};
}

bool crash(injector* self, int camera) {
  auto& st = self->state;
  auto it = st.net.cameras.find(camera);
  if (it == st.net.cameras.end()) return false;
  if (auto again = st.spawning.find(camera); again != st.spawning.end()) {
    again->second = true;  // recovered earlier in this turn: killed as soon as it exists
  } else {
    if (!it->second) return false;  // already down
    kill_camera(self, camera, it->second);
  }
  link_command cmd;
  cmd.op = link_op::node_down;
  cmd.node = camera;
  tell_links(self, camera, cmd);
  return true;
}

// A recovered camera's worker answered with its handle: it joins the clock, its attachments
// get it, and the turn's commands may go.
void spawned_again(injector* self, int camera, caf::actor handle) {
  auto& st = self->state;
  if (st.lost_cameras.count(camera) != 0) return;  // its worker's loss came first
  const bool crash_again = st.spawning[camera];
  st.spawning.erase(camera);
  st.net.cameras[camera] = handle;
  for (const auto& cam : st.scenario.cameras) {
    if (cam.id != camera || !handle) continue;
    auto info = camera_participant(cam);
    info.host = st.net.host_names[camera];
    self->send(st.clock, join_atom_v, handle, info);
  }
  for (auto& [link, cmd] : st.commands)
    if (cmd.op == link_op::attach && cmd.node == camera && !cmd.handle) cmd.handle = handle;
  if (crash_again && handle) kill_camera(self, camera, st.net.cameras[camera]);
  send_commands(self);
  ack_when_done(self);
}

bool recover(injector* self, int camera) {
  auto& st = self->state;
  if (st.lost_cameras.count(camera) != 0) {
    spdlog::warn("faults: camera {} cannot recover: its worker was lost", camera);
    return false;
  }
  auto& slot = st.net.cameras[camera];
  if (slot || st.spawning.count(camera) != 0) return false;  // it did not go down, or is back
  for (const auto& cam : st.scenario.cameras) {
    if (cam.id != camera) continue;
    link_command cmd;
    cmd.op = link_op::attach;
    cmd.node = camera;
    if (auto host = st.net.hosts.find(camera); host != st.net.hosts.end()) {
      // Its worker spawns it again; the attachments take their place in this turn's commands
      // now and the handle when it comes.
      camera_placement p;
      p.camera = camera;
      for (const auto& [neighbour, link] : st.net.links[camera])
        p.links.push_back({neighbour, link.participant, link.handle});
      st.spawning[camera] = false;
      self->request(host->second, caf::infinite, spawn_cameras_atom_v,
                    std::vector<camera_placement>{std::move(p)})
          .then(
              [self, camera](std::vector<caf::actor>& handles) {
                spawned_again(self, camera, handles.empty() ? caf::actor{} : handles.front());
              },
              [self, camera](caf::error& err) {
                // The worker is gone: the clock ends the run for it (docs/distributed.md).
                spdlog::error("faults: camera {} cannot recover: {}", camera,
                              self->system().render(err));
                spawned_again(self, camera, caf::actor{});
              });
      tell_links(self, camera, cmd);
      return true;
    }
    slot = spawn_camera_node(self->system(), st.scenario, cam, st.net.links[camera], st.net.world);
    self->send(st.clock, join_atom_v, slot, camera_participant(cam));
    cmd.handle = slot;
    tell_links(self, camera, cmd);
    return true;
  }
  return false;
}

// The cameras of a lost worker (those it hosted, up or already down) go down as crashed ones
// do, without a kill (they are gone already), and never come back. The links that outlive
// them (the coordinator's, docs/distributed.md) hear they are down; those the worker hosted
// went with it, and are told nothing: nothing would answer.
void take_down_lost(injector* self, tick_context& ctx) {
  auto& st = self->state;
  for (const auto& lost : st.lost) {
    const std::set<std::uint64_t> gone(lost.participants.begin(), lost.participants.end());
    std::vector<int> cameras;
    for (const auto& [camera, host] : st.net.host_names)
      if (host == lost.host) cameras.push_back(camera);
    spdlog::warn("faults: worker {} was lost in tick {}: cameras {} are down for good", lost.host,
                 lost.tick, fmt::join(cameras, ", "));
    link_command cmd;
    cmd.op = link_op::node_down;
    for (const int camera : cameras) {
      st.lost_cameras.insert(camera);
      auto& handle = st.net.cameras[camera];
      const bool was_up = static_cast<bool>(handle) || st.spawning.count(camera) != 0;
      handle = caf::actor{};
      // Recovering on that worker: its handle will never come, nor its attachments go.
      if (st.spawning.erase(camera) != 0)
        st.commands.erase(std::remove_if(st.commands.begin(), st.commands.end(),
                                         [&](const auto& c) {
                                           return c.second.op == link_op::attach &&
                                                  c.second.node == camera && !c.second.handle;
                                         }),
                          st.commands.end());
      cmd.node = camera;
      for (const auto& [neighbour, link] : st.net.links[camera])
        if (gone.count(link.participant) == 0) st.commands.emplace_back(link.handle, cmd);
      ctx.emit(events::fault_event{.fault = "worker_lost",
                                   .camera = camera,
                                   .peer = std::nullopt,
                                   .random = false,
                                   .applied = was_up});
    }
  }
  st.lost.clear();
}

void perform(injector* self, tick_context& ctx, const planned& p) {
  auto& st = self->state;
  const auto& f = st.scenario.faults[p.fault];
  if (p.recovery || f.kind == config::fault_kind::recover) {
    bool applied = recover(self, f.camera);
    ctx.emit(events::node_recovered{.camera = f.camera, .applied = applied});
    return;
  }
  bool applied = true;
  link_command cmd;
  cmd.node = f.camera;
  switch (f.kind) {
    case config::fault_kind::crash:
    case config::fault_kind::crash_and_recover:
      applied = crash(self, f.camera);
      break;
    case config::fault_kind::link_cut:
      cmd.op = link_op::cut;
      tell_link(self, f.camera, *f.peer, cmd);
      break;
    case config::fault_kind::link_heal:
      cmd.op = link_op::heal;
      tell_link(self, f.camera, *f.peer, cmd);
      break;
    case config::fault_kind::loss_burst:
      cmd.op = link_op::loss_burst;
      cmd.loss_probability = f.loss_probability;
      cmd.until_tick = ctx.tick() + config::to_ticks(f.length, st.scenario.run.tick);
      tell_links(self, f.camera, cmd);
      break;
    case config::fault_kind::delay_spike:
      cmd.op = link_op::delay_spike;
      cmd.until_tick = ctx.tick() + config::to_ticks(f.length, st.scenario.run.tick);
      cmd.extra_ticks = config::to_ticks(f.delay, st.scenario.run.tick);
      tell_links(self, f.camera, cmd);
      break;
    case config::fault_kind::recover:
      break;  // above
  }
  ctx.emit(events::fault_event{.fault = std::string(config::yaml_name(f.kind)),
                               .camera = f.camera,
                               .peer = f.peer,
                               .random = false,
                               .applied = applied});
}

void random_failures(injector* self, tick_context& ctx) {
  auto& st = self->state;
  if (st.failure_per_tick <= 0.0) return;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (auto& [camera, handle] : st.net.cameras) {
    // One draw per camera per tick, alive or not, so one failure never shifts the others.
    bool fails = unit(st.rng) < st.failure_per_tick;
    if (fails && (handle || st.spawning.count(camera) != 0) && crash(self, camera))
      ctx.emit(events::fault_event{.fault = "crash",
                                   .camera = camera,
                                   .peer = std::nullopt,
                                   .random = true,
                                   .applied = true});
  }
}

// The operator's fault commands that came in since the last turn, carried out now as faults
// of the scenario at this tick (live::apply_commands makes the same ones for a replay).
void take_live_commands(injector* self, tick_context& ctx) {
  auto& st = self->state;
  for (const auto& c : st.live->queue.take(/*tasks=*/false)) {
    config::fault f;
    f.at = config::to_seconds(ctx.tick(), st.scenario.run.tick);
    f.camera = c.camera;
    switch (c.kind) {
      case live::command_kind::crash:
        f.kind = config::fault_kind::crash;
        break;
      case live::command_kind::recover:
        f.kind = config::fault_kind::recover;
        break;
      case live::command_kind::cut:
        f.kind = config::fault_kind::link_cut;
        f.peer = c.peer;
        break;
      case live::command_kind::heal:
        f.kind = config::fault_kind::link_heal;
        f.peer = c.peer;
        break;
      case live::command_kind::task:
      case live::command_kind::cancel:
        continue;  // the scenario script's
    }
    st.scenario.faults.push_back(f);
    perform(self, ctx, planned{ctx.tick(), st.scenario.faults.size() - 1, false});
    st.live->log.add({ctx.tick(), c});
  }
}

std::vector<planned> make_plan(const config::scenario& s) {
  std::vector<planned> out;
  for (std::size_t i = 0; i < s.faults.size(); ++i) {
    const auto& f = s.faults[i];
    out.push_back({config::to_ticks(f.at, s.run.tick), i, false});
    if (f.kind == config::fault_kind::crash_and_recover)
      out.push_back({config::to_ticks(f.at + f.length, s.run.tick), i, true});
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const planned& a, const planned& b) { return a.tick < b.tick; });
  return out;
}

caf::behavior fault_injector(injector* self, config::scenario scenario, caf::actor clock,
                             network_directory net, std::shared_ptr<live::session> live) {
  auto& st = self->state;
  st.live = std::move(live);
  st.info = fault_injector_participant(scenario, st.live != nullptr);
  st.plan = make_plan(scenario);
  st.rng.seed(config::derive_seed(scenario.run.seed, st.info.id));
  // Table 2's failure probability is read per second of virtual time (docs/network.md).
  st.failure_per_tick =
      1.0 - std::pow(1.0 - scenario.network.node_failure_probability, scenario.run.tick.count());
  st.scenario = std::move(scenario);
  st.clock = std::move(clock);
  st.net = std::move(net);
  self->set_down_handler([self](caf::down_msg& msg) {
    if (self->state.dying.erase(msg.source) == 0) return;
    send_commands(self);
    ack_when_done(self);
  });
  return {
      [self](tick_atom, std::int64_t tick, std::uint8_t, std::uint32_t) {
        auto& st = self->state;
        st.tick = tick;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        take_down_lost(self, ctx);
        while (st.next < st.plan.size() && st.plan[st.next].tick <= tick)
          perform(self, ctx, st.plan[st.next++]);
        if (st.live) take_live_commands(self, ctx);
        random_failures(self, ctx);
        if (st.next < st.plan.size()) ctx.wake_at(st.plan[st.next].tick);
        st.held_ack = std::move(ctx).finish();
        send_commands(self);
        ack_when_done(self);
      },
      [self](lost_worker& lost) { self->state.lost.push_back(std::move(lost)); },
  };
}

}  // namespace

caf::error crash_reason() {
  return caf::error{1, caf::atom("crash")};
}

participant_info fault_injector_participant(const config::scenario& scenario, bool live) {
  participant_info info;
  info.id = participant_ids::fault_injector;
  info.name = "faults";
  info.tick_phase = phase::faults;
  info.mode = scenario.network.node_failure_probability > 0.0 || live ? wake_mode::every_tick
                                                                      : wake_mode::on_demand;
  return info;
}

caf::actor spawn_fault_injector(caf::actor_system& system, const config::scenario& scenario,
                                caf::actor clock, network_directory directory,
                                std::shared_ptr<live::session> live) {
  return system.spawn(fault_injector, scenario, std::move(clock), std::move(directory),
                      std::move(live));
}

}  // namespace argus::actors
