#include "sensing/sensor_kinds.hpp"

#include "sensing/operator_view.hpp"
#include "sensing/task_targets.hpp"
#include "vision/emulated_sensor.hpp"
#include "world/snapshot.hpp"

namespace argus::sensing {

std::vector<controller::look_result> pixel_sensing::look(
    const sensed_frame& frame, const std::vector<controller::look_request>& looks,
    const candidate_filter& admit) {
  if (frame.image.empty()) return {};
  pixel_sensor::truth_check check;
  if (admit)
    check = [&admit](controller::task_id task, const cv::Rect& box) {
      return admit(candidate{task, cv::Rect2d(box), 0});
    };
  return pixels_.look(frame.image, frame.view.pose, looks, check);
}

protocol::signature pixel_sensing::acquire(controller::task_id task, const sensed_frame& frame,
                                           const cv::Rect2d& box) {
  return pixels_.acquire(task, frame.image, frame.view.pose, cv::Rect(box));
}

std::vector<controller::look_result> emulated_sensing::look(
    const sensed_frame& frame, const std::vector<controller::look_request>& looks,
    const candidate_filter& admit) {
  emulated_looks::truth_check check;
  if (admit)
    check = [&admit](controller::task_id task, int id) {
      return admit(candidate{task, std::nullopt, id});
    };
  return looks_.look(*frame.truth, *frame.station, frame.view, looks, check);
}

protocol::signature emulated_sensing::acquire(controller::task_id task, const sensed_frame& frame,
                                              const cv::Rect2d& box) {
  int best = 0;
  double best_overlap = 0.0;
  for (const auto& v : vision::visible_pedestrians(*frame.truth, *frame.station, frame.view)) {
    const auto shown = operator_box(v, frame.view);
    if (!shown) continue;
    const double overlap = (*shown & box).area() / (*shown | box).area();
    if (overlap > best_overlap) {
      best_overlap = overlap;
      best = v.id;
    }
  }
  if (best == 0)
    best = pedestrian_at(*frame.truth, *frame.station, frame.view,
                         cv::Point2d(box.x + box.width / 2, box.y + box.height / 2));
  if (best == 0) return {};
  return looks_.acquire(task, *frame.truth, best);
}

std::unique_ptr<sensor> make_sensor(const config::scenario& scenario,
                                    const config::camera_settings& camera,
                                    const vision::sensor_model& model) {
  if (scenario.sensing.mode == config::sensing_mode::pixels)
    return std::make_unique<pixel_sensing>(pixel_sensor::settings_for(scenario.sensing));
  return std::make_unique<emulated_sensing>(model, scenario.run.seed, camera.id);
}

std::optional<vision::imaging_model> imaging_for(const config::scenario& scenario,
                                                 const config::camera_settings& camera) {
  if (scenario.sensing.mode != config::sensing_mode::pixels) return std::nullopt;
  return vision::imaging_model::for_camera(camera.imaging, scenario.run.seed, camera.id);
}

}  // namespace argus::sensing
