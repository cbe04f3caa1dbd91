#include "actors/scenario_script.hpp"

#include <cmath>
#include <string_view>
#include <vector>

#include "actors/camera_node.hpp"
#include "actors/participant_ids.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "fmt/format.h"

namespace argus::actors {
namespace {

enum class action_kind { task, fault, recover };

struct action {
  std::int64_t tick = 0;
  action_kind kind = action_kind::task;
  std::size_t index = 0;  // into scenario.tasks or scenario.faults
};

struct script_state {
  participant_info info;
  config::scenario scenario;
  caf::actor clock;
  std::map<int, caf::actor> cameras;
  std::vector<action> actions;  // sorted by tick, then by file order
  std::size_t next = 0;
};

std::string_view fault_name(config::fault_kind k) {
  switch (k) {
    case config::fault_kind::crash:
      return "crash";
    case config::fault_kind::crash_and_recover:
      return "crash_and_recover";
    case config::fault_kind::link_cut:
      return "link_cut";
    case config::fault_kind::link_heal:
      return "link_heal";
    case config::fault_kind::loss_burst:
      return "loss_burst";
  }
  return "unknown";
}

std::int64_t to_tick(config::seconds at, config::seconds tick) {
  return static_cast<std::int64_t>(std::llround(at / tick));
}

std::vector<action> plan(const config::scenario& s) {
  std::vector<action> out;
  for (std::size_t i = 0; i < s.tasks.size(); ++i)
    out.push_back({to_tick(s.tasks[i].at, s.run.tick), action_kind::task, i});
  for (std::size_t i = 0; i < s.faults.size(); ++i) {
    const auto& f = s.faults[i];
    out.push_back({to_tick(f.at, s.run.tick), action_kind::fault, i});
    if (f.kind == config::fault_kind::crash_and_recover)
      out.push_back({to_tick(f.at + f.length, s.run.tick), action_kind::recover, i});
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const action& a, const action& b) { return a.tick < b.tick; });
  return out;
}

void crash(caf::stateful_actor<script_state>* self, int camera_id) {
  auto& st = self->state;
  auto it = st.cameras.find(camera_id);
  if (it == st.cameras.end() || !it->second) return;
  self->send(st.clock, retire_atom_v, participant_ids::camera(camera_id));
  self->send_exit(it->second, caf::exit_reason::kill);
  it->second = caf::actor{};
}

void recover(caf::stateful_actor<script_state>* self, int camera_id) {
  auto& st = self->state;
  auto& slot = st.cameras[camera_id];
  if (slot) return;  // never crashed, or already back
  for (const auto& cam : st.scenario.cameras) {
    if (cam.id != camera_id) continue;
    slot = spawn_camera_node(self->system(), cam);
    self->send(st.clock, join_atom_v, slot, camera_participant(cam));
  }
}

void perform(caf::stateful_actor<script_state>* self, const action& a, tick_context& ctx) {
  auto& s = self->state.scenario;
  switch (a.kind) {
    case action_kind::task: {
      const auto& t = s.tasks[a.index];
      ctx.emit("task_issued",
               fmt::format(R"("task":{},"pedestrian":{},"camera":{},"cameras_wanted":{})", a.index,
                           t.pedestrian, t.camera, t.cameras_wanted));
      break;
    }
    case action_kind::fault: {
      const auto& f = s.faults[a.index];
      bool applied =
          f.kind == config::fault_kind::crash || f.kind == config::fault_kind::crash_and_recover;
      auto peer = f.peer ? fmt::format(R"(,"peer":{})", *f.peer) : std::string{};
      ctx.emit("fault", fmt::format(R"("fault":"{}","camera":{}{},"applied":{})",
                                    fault_name(f.kind), f.camera, peer, applied));
      if (applied) crash(self, f.camera);
      break;
    }
    case action_kind::recover: {
      const auto& f = s.faults[a.index];
      recover(self, f.camera);
      ctx.emit("node_recovered", fmt::format(R"("camera":{})", f.camera));
      break;
    }
  }
}

caf::behavior scenario_script(caf::stateful_actor<script_state>* self, config::scenario scenario,
                              caf::actor clock, std::map<int, caf::actor> cameras) {
  auto& st = self->state;
  st.info = script_participant();
  st.actions = plan(scenario);
  st.scenario = std::move(scenario);
  st.clock = std::move(clock);
  st.cameras = std::move(cameras);
  return {
      [self](tick_atom, std::int64_t tick, std::uint8_t) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        while (st.next < st.actions.size() && st.actions[st.next].tick <= tick)
          perform(self, st.actions[st.next++], ctx);
        if (st.next < st.actions.size()) ctx.wake_at(st.actions[st.next].tick);
        self->send(st.clock, std::move(ctx).finish());
      },
  };
}

}  // namespace

participant_info script_participant() {
  return {participant_ids::script, "script", phase::faults, wake_mode::on_demand};
}

caf::actor spawn_scenario_script(caf::actor_system& system, const config::scenario& scenario,
                                 caf::actor clock, std::map<int, caf::actor> cameras) {
  return system.spawn(scenario_script, scenario, std::move(clock), std::move(cameras));
}

}  // namespace argus::actors
