#pragma once

// A still world for camera-node tests under CAF's deterministic coordinator: the station, one
// snapshot of people standing where the test puts them, and an emulated sensor that never
// misses or confuses; and a run of the scenario's cameras, links and fault injector in it.
// Include it after caf/test/dsl.hpp.

#include <map>
#include <memory>
#include <vector>

#include "actors/camera_node.hpp"
#include "actors/clock.hpp"
#include "actors/fault_injector.hpp"
#include "actors/network_assembly.hpp"
#include "protocol/topology.hpp"
#include "world/layout_loader.hpp"

namespace argus::actors::testing {

inline world::pedestrian_state standing(int id, double x, double y, world::rgb8 shirt) {
  world::pedestrian_state p;
  p.id = id;
  p.position = {x, y};
  p.look.shirt = shirt;
  p.look.trousers = {40, 40, 120};
  p.look.skin = {200, 160, 130};
  p.look.hair = {60, 40, 20};
  return p;
}

/// A PTZ camera 6 m up at (x, y), panned `pan` degrees, with a 320 x 240 frame.
inline config::camera_settings mounted(int id, double x, double y, double pan) {
  config::camera_settings c;
  c.id = id;
  c.position = {x, y};
  c.height_m = 6.0;
  c.pan_deg = pan;
  c.imaging.width_px = 320;
  c.imaging.height_px = 240;
  return c;
}

inline std::shared_ptr<camera_world> still_world(const config::scenario& s,
                                                 std::vector<world::pedestrian_state> people) {
  auto world = std::make_shared<camera_world>();
  world->station = world::station::load(world::layout_path(s));
  world->board = std::make_shared<snapshot_board>();
  world->sensor_model.miss_bias = -50.0;  // never misses
  world->sensor_model.confusion_bias = -50.0;
  world->sensor_model.box_sigma = 0.0;
  world->board->publish(std::make_shared<const world::snapshot>(
      *world->station, 0, std::chrono::duration<double>{0.0}, std::move(people)));
  return world;
}

/// Runs `s`'s cameras in `world` for `seconds` on `fixture`'s coordinator; returns the nodes.
template <class Fixture>
std::map<int, caf::actor> run_still(Fixture& fixture, const config::scenario& s,
                                    std::shared_ptr<camera_world> world, double seconds) {
  clock_settings cs;
  cs.end_tick = static_cast<std::int64_t>(seconds * 15.0);
  cs.tick_seconds = s.run.tick.count();
  auto clock = spawn_clock(fixture.sys, cs, fixture.recorder, caf::actor{});
  auto net = spawn_network(fixture.sys, s, protocol::topology(s), clock, std::move(world));
  auto cameras = net.cameras;
  auto faults = spawn_fault_injector(fixture.sys, s, clock, std::move(net));
  fixture.self->send(clock, join_atom_v, faults, fault_injector_participant(s));
  fixture.self->send(clock, start_atom_v);
  fixture.run();
  return cameras;
}

}  // namespace argus::actors::testing
