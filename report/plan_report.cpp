#include "report/plan_report.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>
#include <string>

#include "report/drawing.hpp"
#include "world/plan_view_image.hpp"
#include "world/station.hpp"

namespace argus::report {

namespace {

// Samples further apart than this are not joined: the target left and came back, or rows
// are missing.
constexpr double max_joined_gap_s = 1.0;

class path_painter {
 public:
  path_painter(const world::station& where, cv::Mat& image) : where_(where), image_(image) {}

  cv::Point px(double x_m, double y_m) const {
    const auto [column, row] = world::plan_pixel(where_, options_, world::vec2{x_m, y_m});
    return {column, row};
  }

  void path(int task, const std::vector<target_sample>& samples) {
    const target_sample* first = nullptr;
    const target_sample* last = nullptr;
    for (std::size_t k = 0; k < samples.size(); ++k) {
      const auto& b = samples[k];
      if (!b.present) continue;
      if (first == nullptr) first = &b;
      last = &b;
      if (b.observed_by >= 0) seen_.insert(b.observed_by);
      if (k == 0) continue;
      const auto& a = samples[k - 1];
      if (!a.present || b.t_s - a.t_s > max_joined_gap_s) continue;
      const bgr colour = a.observed_by >= 0 ? camera_colour(a.observed_by) : unobserved_colour;
      cv::line(image_, px(a.x_m, a.y_m), px(b.x_m, b.y_m), scalar_of(colour), 3, cv::LINE_AA);
    }
    if (first == nullptr) return;
    const cv::Point start = px(first->x_m, first->y_m);
    cv::circle(image_, start, 6, cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
    draw_text(image_, "task " + std::to_string(task), start + cv::Point(8, -8), 0.5);
    const cv::Point end = px(last->x_m, last->y_m);
    cv::rectangle(image_, end - cv::Point(5, 5), end + cv::Point(5, 5), cv::Scalar(0, 0, 0), 2);
  }

  void camera_rings(std::span<const config::camera_settings> cameras) {
    for (const auto& c : cameras)
      cv::circle(image_, px(c.position.x_m, c.position.y_m), 9, scalar_of(camera_colour(c.id)), 3,
                 cv::LINE_AA);
  }

  void legend() {
    const int row_px = 18;
    const int rows = static_cast<int>(seen_.size()) + 1;
    const cv::Rect box(8, 8, 130, rows * row_px + 8);
    cv::rectangle(image_, box, cv::Scalar(255, 255, 255), cv::FILLED);
    cv::rectangle(image_, box, cv::Scalar(60, 60, 60), 1);
    int y = box.y + 4;
    auto entry = [&](bgr colour, const std::string& text) {
      cv::line(image_, {box.x + 6, y + row_px / 2}, {box.x + 30, y + row_px / 2}, scalar_of(colour),
               4);
      draw_text(image_, text, {box.x + 36, y + row_px - 5}, 0.45);
      y += row_px;
    };
    for (int camera : seen_) entry(camera_colour(camera), "camera " + std::to_string(camera));
    entry(unobserved_colour, "unobserved");
  }

 private:
  const world::station& where_;
  cv::Mat& image_;
  world::plan_view_options options_;
  std::set<int> seen_;
};

}  // namespace

std::vector<unsigned char> render_plan_report(const world::station& where,
                                              std::span<const config::camera_settings> cameras,
                                              const target_paths& paths) {
  cv::Mat image = world::paint_plan_view(where, cameras, nullptr, nullptr);
  path_painter paint(where, image);
  paint.camera_rings(cameras);
  for (const auto& [task, samples] : paths) paint.path(task, samples);
  paint.legend();
  std::vector<unsigned char> png;
  cv::imencode(".png", image, png);
  return png;
}

}  // namespace argus::report
