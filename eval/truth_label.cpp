#include "eval/truth_label.hpp"

namespace argus::eval {

truth_label label_box(const cv::Rect2d& box, int target,
                      std::span<const vision::pedestrian_view> visible, int width, int height) {
  truth_label out;
  const cv::Rect2d frame(0.0, 0.0, width, height);
  double best = 0.0;
  for (const auto& seen : visible) {
    if (seen.occlusion > max_visible_occlusion) continue;
    const auto shown = seen.box & frame;
    if (shown.area() <= 0.0) continue;
    const double overlap = (box & shown).area();
    // Nearest first: a tie goes to the one in front.
    if (overlap > best) {
      best = overlap;
      out.truth = seen.id;
    }
    if (seen.id == target) {
      const double both = box.area() + shown.area() - overlap;
      out.iou = both > 0.0 ? overlap / both : 0.0;
      const cv::Point2d centre(shown.x + shown.width / 2.0, shown.y + shown.height / 2.0);
      out.observed = box.contains(centre);
    }
  }
  out.observed = out.observed && out.truth == target;
  return out;
}

}  // namespace argus::eval
