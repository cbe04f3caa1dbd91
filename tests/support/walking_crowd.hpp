#pragma once

// The scene the renderer and localisation tests draw: Penn Station with 100 pedestrians, 10 s
// in (seed 3), people spread out and walking. Made once per test executable.

#include <memory>

#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::test_support {

struct walking_crowd_scene {
  std::shared_ptr<const world::station> station;
  std::shared_ptr<const world::snapshot> frame;
};

inline const walking_crowd_scene& walking_crowd() {
  static const walking_crowd_scene scene = [] {
    auto station = world::station::load(world::builtin_layout_path());
    world::crowd_settings settings;
    settings.population = 100;
    settings.run_seed = 3;
    world::crowd crowd(station, settings);
    for (int k = 0; k < 150; ++k) crowd.step();
    return walking_crowd_scene{station, crowd.current()};
  }();
  return scene;
}

}  // namespace argus::test_support
