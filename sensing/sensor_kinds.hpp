#pragma once

#include <memory>
#include <optional>

#include "config/scenario.hpp"
#include "sensing/emulated_looks.hpp"
#include "sensing/pixel_sensor.hpp"
#include "sensing/sensor.hpp"
#include "vision/imaging_model.hpp"
#include "vision/sensor_model.hpp"

namespace argus::sensing {

/// Sensing on the camera's own rendered pixels (pixel_sensor: colour indexing).
class pixel_sensing final : public sensor {
 public:
  explicit pixel_sensing(vision::tracker_settings settings) : pixels_(settings) {}
  bool needs_image() const override { return true; }
  std::vector<controller::look_result> look(const sensed_frame& frame,
                                            const std::vector<controller::look_request>& looks,
                                            const candidate_filter& admit = {}) override;
  bool can_acquire(const sensed_frame& frame) const override { return !frame.image.empty(); }
  protocol::signature acquire(controller::task_id task, const sensed_frame& frame,
                              const cv::Rect2d& box) override;

 private:
  pixel_sensor pixels_;
};

/// Sensing through the emulated sensor (emulated_looks: ground truth through the calibrated
/// error model), for runs too large to render.
class emulated_sensing final : public sensor {
 public:
  emulated_sensing(vision::sensor_model model, std::uint64_t run_seed, int camera_id)
      : looks_(std::move(model), run_seed, camera_id) {}
  bool needs_image() const override { return false; }
  std::vector<controller::look_result> look(const sensed_frame& frame,
                                            const std::vector<controller::look_request>& looks,
                                            const candidate_filter& admit = {}) override;
  bool can_acquire(const sensed_frame&) const override { return true; }
  /// The pedestrian in `box` is the one whose operator box (operator_view.hpp) overlaps it most.
  protocol::signature acquire(controller::task_id task, const sensed_frame& frame,
                              const cv::Rect2d& box) override;

 private:
  emulated_looks looks_;
};

/// The sensor `scenario.sensing.mode` names for `camera` (`model`: the emulated sensor's error
/// model).
std::unique_ptr<sensor> make_sensor(const config::scenario& scenario,
                                    const config::camera_settings& camera,
                                    const vision::sensor_model& model);

/// The imaging model a camera's rendered frames go through: none unless sensing is by pixels.
std::optional<vision::imaging_model> imaging_for(const config::scenario& scenario,
                                                 const config::camera_settings& camera);

}  // namespace argus::sensing
