#include "actors/run_scenario.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <thread>

#include "actors/camera_node.hpp"
#include "actors/clock.hpp"
#include "actors/fault_injector.hpp"
#include "actors/link.hpp"
#include "actors/progress_printer.hpp"
#include "actors/recorder.hpp"
#include "actors/scenario_script.hpp"
#include "actors/system_config.hpp"
#include "actors/type_ids.hpp"
#include "actors/world_coordinator.hpp"
#include "protocol/topology.hpp"
#include "world/layout_loader.hpp"

namespace argus::actors {

std::filesystem::path output_dir_of(const config::scenario& scenario) {
  if (!scenario.run.output_dir.empty()) return scenario.run.output_dir;
  return std::filesystem::path("out") / (scenario.name.empty() ? "run" : scenario.name);
}

run_outcome run_scenario(const config::scenario& scenario, bool show_progress) {
  auto threads = scenario.run.threads != 0 ? scenario.run.threads
                                           : std::max(1u, std::thread::hardware_concurrency());
  system_config cfg(threads);
  caf::actor_system system{cfg};

  run_outcome outcome;
  outcome.output_dir = output_dir_of(scenario);
  const double tick_seconds = scenario.run.tick.count();

  recorder_settings rec;
  rec.output_dir = outcome.output_dir;
  rec.scenario = scenario.name;
  rec.seed = scenario.run.seed;
  rec.tick_seconds = tick_seconds;
  rec.threads = threads;
  rec.speed = scenario.run.speed;
  auto recorder = spawn_recorder(system, rec);

  caf::actor progress;
  if (show_progress) progress = spawn_progress_printer(system, tick_seconds);

  clock_settings cs;
  cs.end_tick = static_cast<std::int64_t>(std::llround(scenario.run.duration / scenario.run.tick));
  cs.tick_seconds = tick_seconds;
  cs.speed = scenario.run.speed;
  auto clock = spawn_clock(system, cs, recorder, progress);

  // Joins and link attachments go out from this thread, in this order, before `start`:
  // enqueued in program order, they all reach their receivers before the first tick.
  protocol::topology topo(scenario);
  network_directory net;
  std::vector<std::pair<caf::actor, participant_info>> links;
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    auto [a, b] = topo.links()[i];
    auto info = link_participant(i, a, b);
    auto handle = spawn_link(system, scenario, i, a, b);
    net.links[a][b] = attached_link{info.id, handle};
    net.links[b][a] = attached_link{info.id, handle};
    links.emplace_back(handle, info);
  }
  for (const auto& cam : scenario.cameras) {
    auto node = spawn_camera_node(system, scenario, cam, net.links[cam.id]);
    net.cameras.emplace(cam.id, node);
    caf::anon_send(clock, join_atom_v, node, camera_participant(cam));
  }
  std::uint64_t seq = 0;
  for (const auto& [camera, neighbours] : net.links)
    for (const auto& [neighbour, link] : neighbours) {
      link_command attach;
      attach.op = link_op::attach;
      attach.node = camera;
      attach.handle = net.cameras.at(camera);
      // Stamped before tick 0, so each link reads it on its first tick.
      caf::anon_send(link.handle, link_cmd_atom_v, mail_stamp{-1, 0, 0, seq++}, attach);
    }
  for (const auto& [handle, info] : links) caf::anon_send(clock, join_atom_v, handle, info);
  auto script = spawn_scenario_script(system, scenario, clock);
  caf::anon_send(clock, join_atom_v, script, script_participant());
  auto faults = spawn_fault_injector(system, scenario, clock, std::move(net));
  caf::anon_send(clock, join_atom_v, faults, fault_injector_participant(scenario));
  world_run_settings world_settings;
  world_settings.station = world::station::load(world::layout_path(scenario));
  world_settings.crowd = world::crowd_settings::from(scenario);
  world_settings.end_tick = cs.end_tick;
  world_settings.trajectories = outcome.output_dir / "trajectories.csv";
  for (auto& [handle, info] : spawn_world(system, std::move(world_settings)).participants)
    caf::anon_send(clock, join_atom_v, handle, info);

  std::string failure;
  {
    caf::scoped_actor self{system};
    self->request(clock, caf::infinite, start_atom_v)
        .receive([&](run_result& r) { outcome.result = std::move(r); },
                 [&](caf::error& err) { failure = system.render(err); });
  }
  if (progress) caf::anon_send_exit(progress, caf::exit_reason::user_shutdown);
  if (!failure.empty()) {
    caf::anon_send_exit(clock, caf::exit_reason::user_shutdown);
    caf::anon_send_exit(recorder, caf::exit_reason::user_shutdown);
    throw std::runtime_error("run failed: " + failure);
  }
  return outcome;
}

}  // namespace argus::actors
