#include "apps/run_overrides.hpp"

#include <cmath>

#include "apps/option_checks.hpp"
#include "config/duration.hpp"
#include "fmt/format.h"

namespace argus::apps {

void add_run_override_options(CLI::App* cmd, run_overrides& into) {
  cmd->add_option("--seed", into.seed, "Run seed (overrides run.seed)")->check(whole_number());
  cmd->add_option("--threads", into.threads,
                  "Threads of the run: CAF's scheduler, the distance fields, a lost worker's "
                  "crowd partitions (0 = all cores)")
      ->check(integer_in(0, 256));
  cmd->add_option("--speed", into.speed,
                  "1 = paced to wall clock, N = N times faster, 0 = free-running")
      ->check(number_in(0.0, HUGE_VAL));
  cmd->add_option("--duration", into.duration, "Virtual duration, e.g. '90 s' or '2 min'");
  cmd->add_option("--out", into.out, "Output directory (default out/<scenario name>)");
}

void apply_run_overrides(const run_overrides& args, config::scenario& s) {
  if (args.seed) s.run.seed = *args.seed;
  if (args.threads) s.run.threads = *args.threads;
  if (args.speed) s.run.speed = *args.speed;
  if (args.out) s.run.output_dir = *args.out;
  if (args.duration) {
    auto d = config::parse_duration(*args.duration);
    if (!d || d->count() <= 0.0)
      throw CLI::ValidationError(
          "--duration",
          fmt::format("expected a positive duration with a unit, e.g. '2 min', got '{}'",
                      *args.duration));
    s.run.duration = *d;
  }
}

}  // namespace argus::apps
