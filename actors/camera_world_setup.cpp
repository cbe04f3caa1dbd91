#include "actors/camera_world_setup.hpp"

#include <utility>

#include "eval/instruments.hpp"

namespace argus::actors {

std::shared_ptr<camera_world> make_camera_world(const config::scenario& scenario,
                                                std::shared_ptr<const world::station> station,
                                                vision::sensor_model model, std::size_t renderers,
                                                std::shared_ptr<eval::observation_log> log) {
  auto out = std::make_shared<camera_world>();
  out->station = station;
  out->board = std::make_shared<snapshot_board>();
  if (scenario.sensing.mode == config::sensing_mode::pixels)
    out->renderers = std::make_shared<shared_renderers>(station, renderers);
  out->sensor_model = std::move(model);
  auto instruments = std::make_shared<const eval::instruments>(
      scenario, station, [board = out->board] { return board->latest(); }, std::move(log));
  out->wrap_sensor = [instruments](const config::camera_settings& camera,
                                   std::unique_ptr<sensing::sensor> sensor) {
    return instruments->wrap(camera, std::move(sensor));
  };
  out->wrap_strategy = [instruments](const config::camera_settings& camera,
                                     std::unique_ptr<controller::strategy> strategy) {
    return instruments->wrap(camera, std::move(strategy));
  };
  out->oracle_for = [instruments](const config::camera_settings& camera) {
    return instruments->oracle_for(camera);
  };
  return out;
}

}  // namespace argus::actors
