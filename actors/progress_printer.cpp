#include "actors/progress_printer.hpp"

#include <cstdio>

#include "actors/type_ids.hpp"
#include "fmt/format.h"

namespace argus::actors {
namespace {

caf::behavior progress_printer(caf::event_based_actor* self, double tick_seconds) {
  self->attach_functor([] { std::fputs("\n", stderr); });
  return {
      [tick_seconds](progress_atom, std::int64_t tick, std::int64_t end_tick, double wall_seconds) {
        double simulated = static_cast<double>(tick) * tick_seconds;
        double total = static_cast<double>(end_tick) * tick_seconds;
        double ratio = wall_seconds > 0.0 ? simulated / wall_seconds : 0.0;
        double eta = ratio > 0.0 ? (total - simulated) / ratio : 0.0;
        auto line = fmt::format(
            "\r  t = {:8.1f} s / {:.1f} s  {:5.1f}%  {:7.1f}x real time  ETA {:6.1f} s ", simulated,
            total, total > 0.0 ? 100.0 * simulated / total : 100.0, ratio, eta);
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
