#include "actors/scenario_script.hpp"

#include <algorithm>
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
  std::vector<std::pair<std::int64_t, std::size_t>> tasks;  // (tick, task index), by tick
  std::size_t next = 0;
};

caf::behavior scenario_script(caf::stateful_actor<script_state>* self, config::scenario scenario,
                              caf::actor clock) {
  auto& st = self->state;
  st.info = script_participant();
  for (std::size_t i = 0; i < scenario.tasks.size(); ++i)
    st.tasks.emplace_back(config::to_ticks(scenario.tasks[i].at, scenario.run.tick), i);
  std::stable_sort(st.tasks.begin(), st.tasks.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  st.scenario = std::move(scenario);
  st.clock = std::move(clock);
  return {
      [self](tick_atom, std::int64_t tick, std::uint8_t, std::uint32_t) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        for (; st.next < st.tasks.size() && st.tasks[st.next].first <= tick; ++st.next) {
          auto index = st.tasks[st.next].second;
          const auto& t = st.scenario.tasks[index];
          ctx.emit("task_issued",
                   fmt::format(R"("task":{},"pedestrian":{},"camera":{},"cameras_wanted":{})",
                               index, t.pedestrian, t.camera, t.cameras_wanted));
        }
        if (st.next < st.tasks.size()) ctx.wake_at(st.tasks[st.next].first);
        self->send(st.clock, std::move(ctx).finish());
      },
  };
}

}  // namespace

participant_info script_participant() {
  return {participant_ids::script, "script", phase::faults, wake_mode::on_demand};
}

caf::actor spawn_scenario_script(caf::actor_system& system, const config::scenario& scenario,
                                 caf::actor clock) {
  return system.spawn(scenario_script, scenario, std::move(clock));
}

}  // namespace argus::actors
