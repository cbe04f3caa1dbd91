// Ticks per second of the bare clock (issue #2): N participants that do nothing but take part,
// on 1 and 2 scheduler threads, either
// - "never woken": on-demand participants that are ticked once, when they join, and never
//   again; what remains per tick is the clock's own loop with an empty calendar (what an idle
//   link or a sleeping node costs), not a barrier over N participants; or
// - "busy": ticked every tick and acknowledging every tick, the full barrier round trip.
// A run the clock reports as failed fails the benchmark (SkipWithError): it has no time to add.
//
//   build/bench/clock_bench --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <variant>

#include "actors/clock.hpp"
#include "actors/recorder.hpp"
#include "actors/system_config.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"

namespace {

using namespace argus::actors;

caf::behavior bare_participant(caf::event_based_actor* self, std::uint64_t id) {
  return {
      [self, id](tick_atom, std::int64_t tick, std::uint8_t, std::uint32_t) {
        tick_ack ack;
        ack.participant = id;
        ack.tick = tick;
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ack));
      },
  };
}

// Returns the wall seconds the clock reports for `ticks` ticks, or the clock's error.
std::variant<double, std::string> run_clock(std::int64_t participants, unsigned threads, bool busy,
                                            bool own_thread, scheduling_order order,
                                            std::int64_t ticks) {
  system_config cfg(threads, order);
  caf::actor_system sys{cfg};
  recorder_settings rs;
  rs.output_dir = std::filesystem::temp_directory_path() / "argus-clock-bench";
  auto recorder = spawn_recorder(sys, rs);
  clock_settings cs;
  cs.end_tick = ticks;
  cs.own_thread = own_thread;
  auto clock = spawn_clock(sys, cs, recorder, caf::actor{});
  // Participants spread over the three phases after `faults`.
  for (std::int64_t i = 0; i < participants; ++i) {
    auto id = static_cast<std::uint64_t>(i + 1);
    participant_info info{id, "p", static_cast<phase>(1 + i % 3),
                          busy ? wake_mode::every_tick : wake_mode::on_demand};
    caf::anon_send(clock, join_atom_v, sys.spawn(bare_participant, id), info);
  }
  std::variant<double, std::string> out = std::string("no answer from the clock");
  caf::scoped_actor self{sys};
  self->request(clock, caf::infinite, start_atom_v)
      .receive([&](run_result& r) { out = r.wall_seconds; },
               [&](caf::error& err) { out = "the clock failed: " + sys.render(err); });
  return out;
}

void bm_clock(benchmark::State& state) {
  auto participants = state.range(0);
  auto threads = static_cast<unsigned>(state.range(1));
  bool busy = state.range(2) != 0;
  bool own_thread = state.range(3) != 0;
  auto order = state.range(4) != 0 ? scheduling_order::caf_default : scheduling_order::turn_order;
  // Enough ticks for a stable figure, few enough to finish when each tick is expensive.
  std::int64_t ticks = busy ? std::clamp<std::int64_t>(400'000 / participants, 20, 20'000) : 20'000;
  double total_wall = 0.0;
  std::int64_t total_ticks = 0;
  for (auto _ : state) {
    auto result = run_clock(participants, threads, busy, own_thread, order, ticks);
    if (const auto* why = std::get_if<std::string>(&result)) {
      state.SkipWithError(why->c_str());
      return;
    }
    double wall = std::get<double>(result);
    state.SetIterationTime(wall);
    total_wall += wall;
    total_ticks += ticks;
  }
  state.counters["ticks_per_s"] =
      total_wall > 0 ? static_cast<double>(total_ticks) / total_wall : 0;
  state.SetLabel(busy ? "busy: every participant every tick" : "never woken after joining");
}

void clock_args(benchmark::internal::Benchmark* b) {
  // With 2 workers, the clock on a worker (clock_thread 0) and on its own thread (1); CAF's
  // scheduling order (caf_order 1) as the baseline for Argus's turn order (0).
  for (int caf_order : {0, 1})
    for (int busy : {0, 1})
      for (int threads : {1, 2})
        for (int own : {0, 1})
          for (int n : {10, 100, 1000, 10000})
            if (threads > 1 || own == 0) b->Args({n, threads, busy, own, caf_order});
}

BENCHMARK(bm_clock)
    ->Apply(clock_args)
    ->ArgNames({"participants", "threads", "busy", "clock_thread", "caf_order"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
