#include "actors/scenario_script.hpp"

#include <algorithm>
#include <tuple>
#include <vector>

#include "actors/participant_ids.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "config/enum_names.hpp"
#include "config/ticks.hpp"
#include "fmt/format.h"

namespace argus::actors {
namespace {

// (tick, task index, is a cancellation).
using step = std::tuple<std::int64_t, std::size_t, bool>;

struct script_state {
  participant_info info;
  config::scenario scenario;
  caf::actor clock;
  // By tick, then task, a task's issue before its cancellation: the order in which a scenario's
  // entries are carried out, and live ones with them.
  std::vector<step> steps;
  std::size_t next = 0;
  std::shared_ptr<eval::observation_log> log;
  std::shared_ptr<live::session> live;
  std::shared_ptr<operator_board> operators;
};

events::task_issued issued(std::uint32_t index, const config::operator_task& t) {
  events::task_issued e{.task = index,
                        .by = std::string(config::yaml_name(t.by)),
                        .pedestrian = std::nullopt,
                        .pixel = std::nullopt,
                        .camera = t.camera,
                        .cameras_wanted = t.cameras_wanted};
  if (t.by == config::task_target::pedestrian) e.pedestrian = t.pedestrian;
  if (t.by == config::task_target::pixel) e.pixel = std::vector<double>{t.pixel.x_px, t.pixel.y_px};
  return e;
}

// The operator's commands that came in since the last turn become this tick's entries, as
// `live::apply_commands` makes them for a replay.
void take_live_commands(script_state& st, std::int64_t tick) {
  auto commands = st.live->queue.take(/*tasks=*/true);
  if (commands.empty()) return;
  const auto at = config::to_seconds(tick, st.scenario.run.tick);
  for (auto& c : commands) {
    if (c.kind == live::command_kind::task) {
      const auto t = live::operator_task_of(c, at);
      const auto index = st.scenario.tasks.size();
      st.scenario.tasks.push_back(t);
      st.steps.emplace_back(tick, index, false);
      st.operators->publish({tick, t.camera, static_cast<std::uint32_t>(index), false, t});
      c.task = static_cast<int>(index);
      st.live->log.add({tick, c});
      continue;
    }
    const auto index = static_cast<std::size_t>(c.task);
    const bool exists = c.task >= 0 && index < st.scenario.tasks.size();
    const char* refusal =
        !exists ? "there is no such task"
        : config::to_ticks(st.scenario.tasks[index].at, st.scenario.run.tick) > tick
            ? "it has not been issued yet"
        : st.scenario.tasks[index].cancel_at ? "it is already cancelled"
                                             : nullptr;
    if (refusal != nullptr) {
      st.live->console.note(fmt::format("cancel of task {} refused: {}", c.task, refusal));
      continue;
    }
    auto& t = st.scenario.tasks[index];
    t.cancel_at = at;
    st.steps.emplace_back(tick, index, true);
    st.operators->publish({tick, t.camera, static_cast<std::uint32_t>(index), true, {}});
    st.live->log.add({tick, c});
  }
  std::sort(st.steps.begin() + static_cast<std::ptrdiff_t>(st.next), st.steps.end());
}

caf::behavior scenario_script(caf::stateful_actor<script_state>* self, config::scenario scenario,
                              caf::actor clock, std::shared_ptr<eval::observation_log> log,
                              std::shared_ptr<live::session> live,
                              std::shared_ptr<operator_board> operators) {
  auto& st = self->state;
  st.live = live && operators ? std::move(live) : nullptr;
  st.operators = std::move(operators);
  st.info = script_participant(st.live != nullptr);
  for (std::size_t i = 0; i < scenario.tasks.size(); ++i) {
    const auto& t = scenario.tasks[i];
    st.steps.emplace_back(config::to_ticks(t.at, scenario.run.tick), i, false);
    if (t.cancel_at)
      st.steps.emplace_back(config::to_ticks(*t.cancel_at, scenario.run.tick), i, true);
  }
  std::sort(st.steps.begin(), st.steps.end());
  st.scenario = std::move(scenario);
  st.clock = std::move(clock);
  st.log = std::move(log);
  return {
      [self](tick_atom, std::int64_t tick, std::uint8_t, std::uint32_t) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        if (st.live) take_live_commands(st, tick);
        for (; st.next < st.steps.size() && std::get<0>(st.steps[st.next]) <= tick; ++st.next) {
          const auto [at, index, cancel] = st.steps[st.next];
          const auto& t = st.scenario.tasks[index];
          if (cancel) {
            ctx.emit(events::task_cancelled{.task = static_cast<std::uint32_t>(index),
                                            .camera = t.camera});
            if (st.log) st.log->add_cancel(static_cast<std::uint32_t>(index), at);
            continue;
          }
          ctx.emit(issued(static_cast<std::uint32_t>(index), t));
        }
        if (st.next < st.steps.size()) ctx.wake_at(std::get<0>(st.steps[st.next]));
        self->send(st.clock, std::move(ctx).finish());
      },
  };
}

}  // namespace

participant_info script_participant(bool live) {
  return {participant_ids::script, "script", phase::faults,
          live ? wake_mode::every_tick : wake_mode::on_demand};
}

caf::actor spawn_scenario_script(caf::actor_system& system, const config::scenario& scenario,
                                 caf::actor clock, std::shared_ptr<eval::observation_log> log,
                                 std::shared_ptr<live::session> live,
                                 std::shared_ptr<operator_board> operators) {
  return system.spawn(scenario_script, scenario, std::move(clock), std::move(log), std::move(live),
                      std::move(operators));
}

}  // namespace argus::actors
