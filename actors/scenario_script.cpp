#include "actors/scenario_script.hpp"

#include <algorithm>
#include <tuple>
#include <vector>

#include "actors/participant_ids.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "config/ticks.hpp"
#include "fmt/format.h"

namespace argus::actors {
namespace {

struct script_state {
  participant_info info;
  config::scenario scenario;
  caf::actor clock;
  // (tick, task index, is a cancellation), by tick.
  std::vector<std::tuple<std::int64_t, std::size_t, bool>> steps;
  std::size_t next = 0;
  std::shared_ptr<eval::observation_log> log;
};

std::string target_fields(const config::operator_task& t) {
  switch (t.by) {
    case config::task_target::pedestrian:
      return fmt::format(R"("by":"pedestrian","pedestrian":{},"camera":{})", t.pedestrian,
                         t.camera);
    case config::task_target::pixel:
      return fmt::format(R"("by":"pixel","pixel":[{},{}],"camera":{})", t.pixel.x_px, t.pixel.y_px,
                         t.camera);
    case config::task_target::first_to_enter:
      return fmt::format(R"("by":"first_to_enter","camera":{})", t.camera);
  }
  return {};
}

caf::behavior scenario_script(caf::stateful_actor<script_state>* self, config::scenario scenario,
                              caf::actor clock, std::shared_ptr<eval::observation_log> log) {
  auto& st = self->state;
  st.info = script_participant();
  for (std::size_t i = 0; i < scenario.tasks.size(); ++i) {
    const auto& t = scenario.tasks[i];
    st.steps.emplace_back(config::to_ticks(t.at, scenario.run.tick), i, false);
    if (t.cancel_at)
      st.steps.emplace_back(config::to_ticks(*t.cancel_at, scenario.run.tick), i, true);
  }
  std::stable_sort(st.steps.begin(), st.steps.end(),
                   [](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
  st.scenario = std::move(scenario);
  st.clock = std::move(clock);
  st.log = std::move(log);
  return {
      [self](tick_atom, std::int64_t tick, std::uint8_t, std::uint32_t) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        for (; st.next < st.steps.size() && std::get<0>(st.steps[st.next]) <= tick; ++st.next) {
          const auto [at, index, cancel] = st.steps[st.next];
          const auto& t = st.scenario.tasks[index];
          if (cancel) {
            ctx.emit("task_cancelled", fmt::format(R"("task":{},"camera":{})", index, t.camera));
            if (st.log) st.log->add_cancel(static_cast<std::uint32_t>(index), at);
            continue;
          }
          ctx.emit("task_issued", fmt::format(R"("task":{},{},"cameras_wanted":{})", index,
                                              target_fields(t), t.cameras_wanted));
        }
        if (st.next < st.steps.size()) ctx.wake_at(std::get<0>(st.steps[st.next]));
        self->send(st.clock, std::move(ctx).finish());
      },
  };
}

}  // namespace

participant_info script_participant() {
  return {participant_ids::script, "script", phase::faults, wake_mode::on_demand};
}

caf::actor spawn_scenario_script(caf::actor_system& system, const config::scenario& scenario,
                                 caf::actor clock, std::shared_ptr<eval::observation_log> log) {
  return system.spawn(scenario_script, scenario, std::move(clock), std::move(log));
}

}  // namespace argus::actors
