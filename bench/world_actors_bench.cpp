// Crowd stepping through the actors (issue 3): simulated seconds per wall second for 100,
// 1,000 and 10,000 pedestrians in the Penn Station at 15 Hz — one crowd partition on one
// scheduler thread, two partitions on two — with the clock, the partitions and the world
// coordinator (snapshots, spawning, hand-overs) but no cameras and no trajectory file.
// Compare with crowd_bench, the same crowd stepped without actors.
//
//   build/bench/world_actors_bench --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>

#include "actors/clock.hpp"
#include "actors/recorder.hpp"
#include "actors/system_config.hpp"
#include "actors/type_ids.hpp"
#include "actors/world_coordinator.hpp"
#include "world/layout_loader.hpp"

namespace {

using namespace argus;
using namespace argus::actors;

// Returns the wall seconds the clock reports for `ticks` ticks.
double run_world(unsigned pedestrians, unsigned threads, std::int64_t ticks) {
  static const auto where = world::station::load(world::builtin_layout_path());
  system_config cfg(threads);
  caf::actor_system sys{cfg};
  recorder_settings rs;
  rs.output_dir = std::filesystem::temp_directory_path() / "argus-world-actors-bench";
  auto recorder = spawn_recorder(sys, rs);
  clock_settings cs;
  cs.end_tick = ticks;
  cs.own_thread = clock_on_own_thread(threads, threads + 1);  // partitions + coordinator
  auto clock = spawn_clock(sys, cs, recorder, caf::actor{});
  world_run_settings ws;
  ws.station = where;
  ws.crowd.run_seed = 3;
  ws.crowd.population = pedestrians;
  ws.crowd.spawn_rate_per_min = 600;
  ws.crowd.partitions = threads;
  ws.end_tick = ticks;
  for (auto& [handle, info] : spawn_world(sys, ws).participants)
    caf::anon_send(clock, join_atom_v, handle, info);
  double wall = 0.0;
  caf::scoped_actor self{sys};
  self->request(clock, caf::infinite, start_atom_v)
      .receive([&](run_result& r) { wall = r.wall_seconds; }, [](caf::error&) {});
  return wall;
}

void bm_world_actors(benchmark::State& state) {
  const auto pedestrians = static_cast<unsigned>(state.range(0));
  const auto threads = static_cast<unsigned>(state.range(1));
  // 10 s to 200 s of virtual time: long enough that the crowd is moving, not just placed.
  const std::int64_t ticks = std::clamp<std::int64_t>(600'000 / pedestrians, 150, 3000);
  const double tick_s = 1.0 / 15.0;
  double total_wall = 0.0;
  std::int64_t total_ticks = 0;
  for (auto _ : state) {
    const double wall = run_world(pedestrians, threads, ticks);
    state.SetIterationTime(wall);
    total_wall += wall;
    total_ticks += ticks;
  }
  state.counters["sim_s_per_wall_s"] =
      total_wall > 0 ? static_cast<double>(total_ticks) * tick_s / total_wall : 0.0;
}

void world_args(benchmark::internal::Benchmark* b) {
  for (int threads : {1, 2})
    for (int n : {100, 1000, 10000}) b->Args({n, threads});
}

BENCHMARK(bm_world_actors)
    ->Apply(world_args)
    ->ArgNames({"pedestrians", "threads"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
