#include "sensing/task_targets.hpp"

#include "vision/emulated_sensor.hpp"

namespace argus::sensing {
namespace {

// As operator_box: hidden beyond this, nobody could click on her.
constexpr double max_occlusion = 0.9;

}  // namespace

int pedestrian_at(const world::snapshot& frame, const world::station& where,
                  const vision::camera_view& view, const cv::Point2d& pixel) {
  const cv::Rect2d image(0.0, 0.0, view.width_px, view.height_px);
  // Nearest first: the first box that holds the click is the one in front.
  for (const auto& seen : vision::visible_pedestrians(frame, where, view)) {
    if (seen.occlusion > max_occlusion) continue;
    if ((seen.box & image).contains(pixel)) return seen.id;
  }
  return 0;
}

view_census in_view(const world::snapshot& frame, const world::station& where,
                    const vision::camera_view& view) {
  const cv::Rect2d image(0.0, 0.0, view.width_px, view.height_px);
  // Wholly in view: two pixels clear of every edge, at most a fifth hidden, and near enough to
  // be told apart (a fourteenth of the frame tall): what an operator would call "in the scene".
  const cv::Rect2d inner(2.0, 2.0, view.width_px - 4.0, view.height_px - 4.0);
  const double min_height = view.height_px / 14.0;
  view_census out;
  for (const auto& seen : vision::visible_pedestrians(frame, where, view)) {
    if (seen.occlusion > max_occlusion || (seen.box & image).area() <= 0.0) continue;
    out.seen.insert(seen.id);
    if (seen.occlusion <= 0.2 && (seen.box & inner) == seen.box && seen.box.height >= min_height)
      out.whole.insert(seen.id);
  }
  return out;
}

int entry_watch::step(const view_census& now) {
  if (!primed_) {
    prime(now);
    return 0;
  }
  // Who left the view is no longer a candidate; who entered joins the end of the line.
  std::erase_if(entrants_, [&](int id) { return now.seen.count(id) == 0; });
  for (int id : now.seen)
    if (before_.count(id) == 0) entrants_.push_back(id);
  before_ = now.seen;
  for (int id : entrants_)
    if (now.whole.count(id) != 0) return id;
  return 0;
}

}  // namespace argus::sensing
