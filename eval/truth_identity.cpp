#include "eval/truth_identity.hpp"

#include "eval/truth_label.hpp"
#include "vision/emulated_sensor.hpp"

namespace argus::eval {

std::vector<controller::look_result> truth_identity::look(
    const sensing::sensed_frame& frame, const std::vector<controller::look_request>& looks,
    const sensing::candidate_filter& admit) {
  if (!truth_->log) return inner().look(frame, looks, admit);
  // The visible boxes are computed on the first find asked about.
  std::optional<std::vector<vision::pedestrian_view>> visible;
  sensing::candidate_filter hers = [&](const sensing::candidate& c) {
    const auto target = truth_->log->target_of(c.task);
    if (!target) return false;
    if (!c.box) return *target == c.pedestrian;
    if (!visible) visible = vision::visible_pedestrians(*frame.truth, *frame.station, frame.view);
    return label_box(*c.box, *target, *visible, frame.view.width_px, frame.view.height_px).observed;
  };
  return inner().look(frame, looks, sensing::both(std::move(hers), admit));
}

}  // namespace argus::eval
