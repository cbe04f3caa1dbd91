#include "sensing/pixel_sensor.hpp"

#include <algorithm>

#include "sensing/signature.hpp"

namespace argus::sensing {

pixel_sensor::pixel_sensor(vision::tracker_settings settings) : settings_(settings) {
  // nop
}

vision::tracker_settings pixel_sensor::settings_for(const config::sensing_settings& sensing) {
  vision::tracker_settings settings;
  settings.scales.rule = sensing.scales == config::tracker_scales::paper
                             ? vision::scale_rule::paper
                             : vision::scale_rule::target;
  settings.ego_motion = sensing.ego_motion;
  settings.update_signature = sensing.signature_update;
  settings.reacquire_margin = sensing.reacquire_margin;
  settings.local_search_frames = sensing.local_search_frames;
  settings.max_surround_match = sensing.max_surround_match;
  settings.surround_grace_frames = sensing.surround_grace_frames;
  settings.surround_grace_height_px = sensing.surround_grace_height_px;
  settings.surround_patience_frames = sensing.surround_patience_frames;
  settings.surround_sides = sensing.surround_sides;
  settings.track_rho = sensing.track_rho;
  if (sensing.halves_rho > 0.0) settings.halves_rho = sensing.halves_rho;
  return settings;
}

std::vector<controller::look_result> pixel_sensor::look(
    const cv::Mat& bgr, const vision::ptz_state& pose,
    const std::vector<controller::look_request>& looks, const truth_check& is_target) {
  std::map<controller::task_id, vision::tracker> kept;
  const vision::frame_size frame{bgr.cols, bgr.rows};
  if (settings_.ego_motion && last_pose_)
    for (auto& [task, t] : trackers_) t.follow_camera(*last_pose_, pose, frame);
  last_pose_ = pose;
  std::vector<controller::look_result> out;
  for (const auto& l : looks) {
    auto it = trackers_.find(l.task);
    if (it == trackers_.end())
      it = trackers_
               .emplace(l.task,
                        vision::tracker(to_histogram(l.target), settings_, to_halves(l.target)))
               .first;
    vision::tracker::find_check check;
    if (is_target) check = [&](const cv::Rect& box) { return is_target(l.task, box); };
    const int updates = it->second.model_updates();
    const auto seen = it->second.update(bgr, check);
    out.push_back({l.task, seen.found, cv::Rect2d(seen.box), seen.score, std::nullopt});
    if (it->second.model_updates() != updates)
      out.back().model = to_signature(it->second.model(), it->second.model_halves());
    kept.insert(trackers_.extract(it));
  }
  trackers_ = std::move(kept);
  return out;
}

protocol::signature pixel_sensor::acquire(controller::task_id task, const cv::Mat& bgr,
                                          const vision::ptz_state& pose, const cv::Rect& box) {
  last_pose_ = pose;
  const auto region = box & cv::Rect(0, 0, bgr.cols, bgr.rows);
  auto histogram = vision::color_histogram::of_region(bgr, region);
  std::optional<vision::signature_halves> halves;
  if (settings_.halves_rho)
    halves =
        vision::halves_in(vision::bin_index_image(bgr, histogram.bins()), region, histogram.bins());
  vision::tracker t(histogram.normalized(), settings_, halves);
  t.start(region);
  trackers_.insert_or_assign(task, std::move(t));
  return to_signature(histogram, halves);
}

}  // namespace argus::sensing
