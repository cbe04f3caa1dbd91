// Crowd stepping speed: simulated seconds per wall second for 100, 1,000 and 10,000
// pedestrians in the Penn Station at 15 Hz, one thread, one partition (the multi-threaded
// figure comes from the crowd-partition actors). Reported as the counter
// "sim_s_per_wall_s"; >= 20 for 1,000 and >= 1 for 10,000 are the targets (issue 3).
#include <benchmark/benchmark.h>

#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace {

using namespace argus::world;

void crowd_step(benchmark::State& state) {
  static const auto where = station::load(builtin_layout_path());
  crowd_settings settings;
  settings.run_seed = 3;
  settings.population = static_cast<unsigned>(state.range(0));
  settings.spawn_rate_per_min = 600;
  crowd world(where, settings);
  // Warm up past the initial placement into a moving crowd.
  for (int k = 0; k < 30; ++k) world.step();
  std::int64_t ticks = 0;
  for (auto _ : state) {
    world.step();
    ++ticks;
  }
  const double simulated_s = static_cast<double>(ticks) * settings.behaviour.tick_s;
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
  state.counters["pedestrians"] = static_cast<double>(world.current()->pedestrians().size());
}

BENCHMARK(crowd_step)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
