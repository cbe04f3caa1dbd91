#include "actors/progress_printer.hpp"

#include <cstdio>
#include <map>

#include "actors/type_ids.hpp"
#include "fmt/format.h"
#include "nlohmann/json.hpp"

namespace argus::actors {
namespace {

// Who is in each task's group, by camera: true for its leader.
using groups = std::map<int, std::map<int, bool>>;

void apply(groups& g, const sim_event& ev) {
  const auto f = nlohmann::json::parse("{" + ev.fields_json + "}", nullptr, false);
  if (f.is_discarded() || !f.contains("camera") || !f.contains("task")) return;
  const int camera = f["camera"].get<int>();
  const int task = f["task"].get<int>();
  if (ev.kind == "left_task") {
    g[task].erase(camera);
  } else if (ev.kind == "task_created") {
    g[task][camera] = true;
  } else if (ev.kind == "joined") {
    g[task][camera] = false;
  } else if (ev.kind == "leader_changed" && f.contains("leader")) {
    g[task][camera] = f["leader"].get<int>() == camera;
  }
}

// "task 0: camera 3 +1", each task's leader(s) and how many members follow.
std::string describe(const groups& g) {
  std::string out;
  for (const auto& [task, members] : g) {
    std::string leaders;
    int followers = 0;
    for (const auto& [camera, leads] : members) {
      if (leads) {
        if (!leaders.empty()) leaders += ',';
        leaders += std::to_string(camera);
      } else {
        ++followers;
      }
    }
    out += fmt::format(" | task {}: {}", task,
                       leaders.empty() ? std::string("unobserved")
                                       : fmt::format("camera {} +{}", leaders, followers));
  }
  return out;
}

caf::behavior progress_printer(caf::event_based_actor* self, double tick_seconds) {
  self->attach_functor([] { std::fputs("\n", stderr); });
  auto tasks = std::make_shared<groups>();
  return {
      [tasks](record_atom, std::int64_t, std::vector<sim_event>& changes) {
        for (const auto& ev : changes) apply(*tasks, ev);
      },
      [tick_seconds, tasks](progress_atom, std::int64_t tick, std::int64_t end_tick,
                            double wall_seconds) {
        double simulated = static_cast<double>(tick) * tick_seconds;
        double total = static_cast<double>(end_tick) * tick_seconds;
        double ratio = wall_seconds > 0.0 ? simulated / wall_seconds : 0.0;
        double eta = ratio > 0.0 ? (total - simulated) / ratio : 0.0;
        auto line = fmt::format(
            "\r  t = {:8.1f} s / {:.1f} s  {:5.1f}%  {:7.1f}x real time  ETA {:6.1f} s ", simulated,
            total, total > 0.0 ? 100.0 * simulated / total : 100.0, ratio, eta);
        line += describe(*tasks) + "   ";
        std::fputs(line.c_str(), stderr);
        std::fflush(stderr);
      },
  };
}

}  // namespace

caf::actor spawn_progress_printer(caf::actor_system& system, double tick_seconds) {
  return system.spawn(progress_printer, tick_seconds);
}

}  // namespace argus::actors
