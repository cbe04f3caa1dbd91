#pragma once

#include <functional>
#include <memory>

#include "config/scenario.hpp"
#include "controller/strategy_registry.hpp"
#include "eval/observation_log.hpp"
#include "eval/oracle_board.hpp"
#include "eval/position_board.hpp"
#include "eval/sighting_board.hpp"
#include "sensing/sensor.hpp"

namespace argus::eval {

/// A run's instruments, as the scenario turns them on: the observation log every frame is
/// recorded in, sensing.identity, sensing.group_geometry, sensing.reappearance, and the central
/// oracle's ground truth for a strategy registered as an oracle. The host wraps each camera
/// node's sensor and strategy in them; the node itself knows none of them.
class instruments {
 public:
  /// `now`: the world in the current tick.
  instruments(const config::scenario& scenario, std::shared_ptr<const world::station> station,
              std::function<std::shared_ptr<const world::snapshot>()> now,
              std::shared_ptr<observation_log> log);

  /// `camera`'s sensor with the instruments that filter its finds.
  std::unique_ptr<sensing::sensor> wrap(const config::camera_settings& camera,
                                        std::unique_ptr<sensing::sensor> sensor) const;
  /// `camera`'s strategy with the recorder and the instruments that aim it.
  std::unique_ptr<controller::strategy> wrap(const config::camera_settings& camera,
                                             std::unique_ptr<controller::strategy> strategy) const;
  /// Ground truth for `camera`'s strategy, should it be an oracle.
  controller::oracle_source oracle_for(const config::camera_settings& camera) const;

 private:
  std::shared_ptr<const class camera_truth> truth_of(const config::camera_settings& camera) const;

  config::scenario scenario_;
  std::shared_ptr<const world::station> station_;
  std::function<std::shared_ptr<const world::snapshot>()> now_;
  std::shared_ptr<observation_log> log_;
  std::shared_ptr<oracle_board> oracle_;
  std::shared_ptr<sighting_board> sightings_;
  std::shared_ptr<position_board> positions_;
};

}  // namespace argus::eval
