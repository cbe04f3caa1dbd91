#include "sensing/pixel_sensor.hpp"

#include <algorithm>

#include "sensing/signature.hpp"

namespace argus::sensing {

std::vector<controller::look_result> pixel_sensor::look(
    const cv::Mat& bgr, const std::vector<controller::look_request>& looks) {
  std::map<controller::task_id, vision::tracker> kept;
  std::vector<controller::look_result> out;
  for (const auto& l : looks) {
    auto it = trackers_.find(l.task);
    if (it == trackers_.end())
      it = trackers_.emplace(l.task, vision::tracker(to_histogram(l.target))).first;
    const auto seen = it->second.update(bgr);
    out.push_back({l.task, seen.found, cv::Rect2d(seen.box), seen.score});
    kept.insert(trackers_.extract(it));
  }
  trackers_ = std::move(kept);
  return out;
}

protocol::signature pixel_sensor::acquire(controller::task_id task, const cv::Mat& bgr,
                                          const cv::Rect& box) {
  const auto region = box & cv::Rect(0, 0, bgr.cols, bgr.rows);
  auto histogram = vision::color_histogram::of_region(bgr, region);
  vision::tracker t(histogram.normalized());
  t.start(region);
  trackers_.insert_or_assign(task, std::move(t));
  return to_signature(histogram);
}

}  // namespace argus::sensing
