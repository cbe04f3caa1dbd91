#include "apps/chaos_plan.hpp"

#include <algorithm>
#include <set>

#include "config/derive_seed.hpp"
#include "protocol/topology.hpp"
#include "world/rng.hpp"

namespace argus::apps {
namespace {

using config::fault;
using config::fault_kind;
using config::seconds;

// A window [at, at + length) inside [start, end), `length` drawn in [low, high).
std::pair<double, double> window(world::rng& r, double start, double end, double low, double high) {
  const double length = std::min(r.uniform(low, high), std::max(0.0, end - start));
  const double at = r.uniform(start, std::max(start, end - length));
  return {at, length};
}

int any_camera(world::rng& r, const config::scenario& s) {
  return s.cameras[r.below(static_cast<std::uint32_t>(s.cameras.size()))].id;
}

// A fault of `kind` on a random camera, in a window of [low, high) seconds within [start, end).
fault camera_fault(world::rng& r, const config::scenario& s, fault_kind kind, double start,
                   double end, double low, double high) {
  const auto [at, length] = window(r, start, end, low, high);
  fault f;
  f.at = seconds{at};
  f.kind = kind;
  f.camera = any_camera(r, s);
  f.length = seconds{length};
  return f;
}

}  // namespace

chaos_plan plan_chaos(const config::scenario& scenario, std::uint64_t seed,
                      const chaos_settings& settings) {
  chaos_plan plan;
  plan.seed = seed;
  // Its own stream, apart from the run's, which the run seeds with the same number.
  world::rng r(config::derive_seed(seed, 0x6e656d65736973ULL));  // "nemesis"
  plan.merge = seed % 2 == 0 ? config::merge_rule::negotiation : config::merge_rule::highest_id;
  const auto every = settings.scenario_sensing_every;
  plan.sensing =
      every > 0 && seed % every == 0 ? scenario.sensing.mode : config::sensing_mode::emulated;
  const double start = 10.0;
  const double end = std::max(start, (settings.duration - settings.quiet_tail).count());
  plan.healed_at = seconds{end};
  if (scenario.cameras.empty()) return plan;

  for (std::uint32_t k = r.below(3); k > 0; --k) {
    auto f = camera_fault(r, scenario, fault_kind::loss_burst, start, end, 2.0, 10.0);
    f.loss_probability = r.uniform(0.5, 1.0);
    plan.faults.push_back(f);
    plan.nemeses.push_back("loss_burst");
  }
  for (std::uint32_t k = r.below(3); k > 0; --k) {
    auto f = camera_fault(r, scenario, fault_kind::delay_spike, start, end, 2.0, 10.0);
    f.delay = seconds{r.uniform(0.5, 3.0)};
    plan.faults.push_back(f);
    plan.nemeses.push_back("delay_spike");
  }
  if (r.chance(0.6)) {
    std::set<int> side;
    for (const auto& c : scenario.cameras)
      if (r.chance(0.5)) side.insert(c.id);
    const auto [at, length] = window(r, start, end, 5.0, 20.0);
    bool cut_any = false;
    const protocol::topology network(scenario);
    for (const auto& [a, b] : network.links()) {
      if ((side.count(a) != 0) == (side.count(b) != 0)) continue;
      fault cut;
      cut.at = seconds{at};
      cut.kind = fault_kind::link_cut;
      cut.camera = a;
      cut.peer = b;
      fault heal = cut;
      heal.at = seconds{at + length};
      heal.kind = fault_kind::link_heal;
      plan.faults.push_back(cut);
      plan.faults.push_back(heal);
      cut_any = true;
    }
    if (cut_any) plan.nemeses.push_back("partition");
  }
  for (std::uint32_t k = r.below(3); k > 0; --k) {
    plan.faults.push_back(
        camera_fault(r, scenario, fault_kind::crash_and_recover, start, end, 5.0, 30.0));
    plan.nemeses.push_back("crash_and_recover");
  }
  if (r.chance(0.5)) {
    plan.duplicate_probability = r.uniform(0.02, 0.1);
    plan.nemeses.push_back("duplicates");
  }
  plan.reorder = r.chance(0.5);
  if (plan.reorder) plan.nemeses.push_back("reorder");
  if (!scenario.tasks.empty() && r.chance(0.25)) {
    const auto task = r.below(static_cast<std::uint32_t>(scenario.tasks.size()));
    const double from = scenario.tasks[task].at.count() + 10.0;
    if (from < end) {
      plan.cancel = {task, seconds{r.uniform(from, end)}};
      plan.nemeses.push_back("cancel");
    }
  }
  std::stable_sort(plan.faults.begin(), plan.faults.end(),
                   [](const fault& a, const fault& b) { return a.at < b.at; });
  return plan;
}

config::scenario with_chaos(config::scenario scenario, const chaos_plan& plan,
                            const chaos_settings& settings) {
  scenario.run.seed = plan.seed;
  scenario.run.duration = settings.duration;
  scenario.controller.merge = plan.merge;
  scenario.sensing.mode = plan.sensing;
  scenario.network.duplicate_probability = plan.duplicate_probability;
  scenario.network.reorder = plan.reorder;
  scenario.network.node_failure_probability = 0.0;
  scenario.faults = plan.faults;
  if (plan.cancel) scenario.tasks[plan.cancel->first].cancel_at = plan.cancel->second;
  return scenario;
}

}  // namespace argus::apps
