#include "eval/instruments.hpp"

#include "eval/camera_truth.hpp"
#include "eval/floor_sharing.hpp"
#include "eval/frame_recording.hpp"
#include "eval/oracle_camera_view.hpp"
#include "eval/sighting_aim.hpp"
#include "eval/truth_identity.hpp"

namespace argus::eval {

instruments::instruments(const config::scenario& scenario,
                         std::shared_ptr<const world::station> station,
                         std::function<std::shared_ptr<const world::snapshot>()> now,
                         std::shared_ptr<observation_log> log)
    : scenario_(scenario),
      station_(std::move(station)),
      now_(std::move(now)),
      log_(std::move(log)) {
  // Assignments are made only when an oracle asks for them.
  oracle_ = std::make_shared<oracle_board>(scenario, station_, log_);
  // The oracle assigns cameras itself: the group instruments have nothing to aim.
  if (controller::is_oracle(scenario)) return;
  if (scenario.sensing.geometry == config::group_geometry::ground_truth ||
      scenario.sensing.reappearance == config::reappearance_model::ground_truth)
    sightings_ = std::make_shared<sighting_board>();
  if (scenario.sensing.geometry == config::group_geometry::calibrated)
    positions_ = std::make_shared<position_board>();
}

std::shared_ptr<const camera_truth> instruments::truth_of(
    const config::camera_settings& camera) const {
  auto t = std::make_shared<camera_truth>();
  t->camera = camera;
  t->tick_length = scenario_.run.tick;
  t->station = station_;
  t->now = now_;
  t->log = log_;
  return t;
}

std::unique_ptr<sensing::sensor> instruments::wrap(const config::camera_settings& camera,
                                                   std::unique_ptr<sensing::sensor> sensor) const {
  const auto truth = truth_of(camera);
  // Filters apply innermost first: her identity, then where the group says she is.
  if (scenario_.sensing.identity == config::identity_source::ground_truth)
    sensor = std::make_unique<truth_identity>(std::move(sensor), truth);
  if (positions_)
    sensor = std::make_unique<floor_gated_sensor>(
        std::move(sensor), std::make_shared<floor_estimates>(truth, positions_));
  return sensor;
}

std::unique_ptr<controller::strategy> instruments::wrap(
    const config::camera_settings& camera, std::unique_ptr<controller::strategy> strategy) const {
  const auto truth = truth_of(camera);
  // Commands apply innermost first: the strategy's, then the group's sighting, then its floor
  // estimate.
  if (sightings_)
    strategy = std::make_unique<sighting_aim>(
        std::move(strategy), truth, sightings_,
        scenario_.sensing.geometry == config::group_geometry::ground_truth,
        scenario_.sensing.reappearance == config::reappearance_model::ground_truth);
  if (positions_)
    strategy = std::make_unique<floor_sharing_strategy>(
        std::move(strategy), std::make_shared<floor_estimates>(truth, positions_));
  return std::make_unique<frame_recording>(std::move(strategy), truth, sightings_);
}

controller::oracle_source instruments::oracle_for(const config::camera_settings& camera) const {
  return [truth = truth_of(camera), board = oracle_]() -> std::unique_ptr<controller::oracle_view> {
    return std::make_unique<oracle_camera_view>(truth, board);
  };
}

}  // namespace argus::eval
