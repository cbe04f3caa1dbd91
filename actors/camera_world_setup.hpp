#pragma once

#include <cstddef>
#include <memory>

#include "actors/camera_node.hpp"
#include "config/scenario.hpp"
#include "eval/observation_log.hpp"
#include "vision/sensor_model.hpp"
#include "world/station.hpp"

namespace argus::actors {

/// What a run's camera nodes sense with, made the one way for a run in one process and for a
/// worker's part of a distributed one: `station`, a fresh snapshot board, `renderers` EGL
/// renderers when the scenario senses pixels, the emulated sensor's `model`, and the scenario's
/// instruments recording into `log`. The observer, the operator's board and the pose board are
/// the caller's to set.
std::shared_ptr<camera_world> make_camera_world(const config::scenario& scenario,
                                                std::shared_ptr<const world::station> station,
                                                vision::sensor_model model, std::size_t renderers,
                                                std::shared_ptr<eval::observation_log> log);

}  // namespace argus::actors
