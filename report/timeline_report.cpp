#include "report/timeline_report.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>
#include <string>

#include "fmt/format.h"
#include "report/drawing.hpp"

namespace argus::report {

namespace {

constexpr int width_px = 1200;
constexpr int left_px = 200;
constexpr int right_px = 24;
constexpr int title_px = 34;
constexpr int task_header_px = 24;
constexpr int lane_px = 20;
constexpr int gap_px = 10;
constexpr int axis_px = 40;
const cv::Scalar crash_colour(30, 30, 220);
const cv::Scalar recovery_colour(40, 160, 40);
const cv::Scalar link_colour(0, 140, 255);

std::set<int> lanes_of(const task_timeline& task) {
  std::set<int> cameras;
  for (const auto& s : task.members) cameras.insert(s.camera);
  for (const auto& s : task.leaders) cameras.insert(s.camera);
  return cameras;
}

bool is_crash(const failure_mark& f) {
  return f.kind == "crash" || f.kind == "crash_and_recover";
}

// How a fault reads under its mark: the camera, "+N" for a recovery, "cut 2"/"heal 2" for links.
std::string fault_label(const failure_mark& f) {
  if (f.kind == "recovered") return fmt::format("+{}", f.camera);
  if (f.kind == "link_cut") return fmt::format("cut {}", f.camera);
  if (f.kind == "link_heal") return fmt::format("heal {}", f.camera);
  if (f.kind == "loss_burst") return fmt::format("loss {}", f.camera);
  return std::to_string(f.camera);
}

class timeline_painter {
 public:
  explicit timeline_painter(const group_timeline& timeline) : timeline_(timeline) {
    int height = title_px + axis_px + 2 * lane_px + gap_px;  // the faults lane is two high
    for (const auto& task : timeline.tasks)
      height += task_header_px + lane_px * static_cast<int>(lanes_of(task).size()) + gap_px;
    if (timeline.tasks.empty()) height += task_header_px;
    image_ = cv::Mat(height, width_px, CV_8UC3, cv::Scalar(255, 255, 255));
    chart_bottom_ = height - axis_px;
  }

  int x(double t_s) const {
    const double span = std::max(timeline_.end_s, 1e-3);
    return left_px + static_cast<int>(std::lround((width_px - left_px - right_px) * t_s / span));
  }

  cv::Mat draw() {
    draw_text(image_, "task groups over time (thin: member, thick: leader)", {left_px, 22}, 0.55);
    int y = title_px;
    if (timeline_.tasks.empty()) {
      draw_text(image_, "no tasks in this run", {left_px, y + 16});
      y += task_header_px;
    }
    for (const auto& task : timeline_.tasks) y = draw_task(task, y);
    draw_faults_lane(y);
    draw_axis();
    return image_;
  }

 private:
  int draw_task(const task_timeline& task, int y) {
    const std::string title =
        task.pedestrian >= 0 ? fmt::format("task {} (pedestrian {})", task.task, task.pedestrian)
                             : fmt::format("task {}", task.task);
    draw_text(image_, title, {8, y + 16}, 0.5);
    cv::line(image_, {x(task.start_s), y + task_header_px - 4},
             {x(task.end_s), y + task_header_px - 4}, cv::Scalar(200, 200, 200), 1);
    for (double t : task.handoffs_s) {
      const cv::Point tip(x(t), y + task_header_px - 2);
      std::vector<cv::Point> triangle{tip, tip + cv::Point(-5, -9), tip + cv::Point(5, -9)};
      cv::fillPoly(image_, std::vector<std::vector<cv::Point>>{triangle}, ink, cv::LINE_AA);
    }
    y += task_header_px;
    for (int camera : lanes_of(task)) {
      const int middle = y + lane_px / 2;
      draw_text(image_, fmt::format("camera {}", camera), {20, middle + 5});
      cv::line(image_, {left_px, middle}, {width_px - right_px, middle}, cv::Scalar(235, 235, 235),
               1);
      const auto colour = scalar_of(camera_colour(camera));
      for (const auto& s : task.members)
        if (s.camera == camera)
          cv::rectangle(image_, {x(s.from_s), middle - 3},
                        {std::max(x(s.to_s), x(s.from_s) + 1), middle + 3}, colour, cv::FILLED);
      for (const auto& s : task.leaders)
        if (s.camera == camera) {
          const cv::Rect bar({x(s.from_s), middle - 7},
                             cv::Point(std::max(x(s.to_s), x(s.from_s) + 1), middle + 7));
          cv::rectangle(image_, bar, colour, cv::FILLED);
          cv::rectangle(image_, bar, ink, 1);
        }
      for (const auto& f : timeline_.failures)
        if (f.camera == camera && is_crash(f) && f.t_s >= task.start_s && f.t_s <= task.end_s)
          cross(x(f.t_s), middle);
      y += lane_px;
    }
    return y + gap_px;
  }

  void cross(int at_x, int middle) {
    cv::line(image_, {at_x - 6, middle - 6}, {at_x + 6, middle + 6}, crash_colour, 2, cv::LINE_AA);
    cv::line(image_, {at_x - 6, middle + 6}, {at_x + 6, middle - 6}, crash_colour, 2, cv::LINE_AA);
  }

  void draw_faults_lane(int y) {
    const int middle = y + lane_px / 2;
    draw_text(image_, "faults", {20, middle + 5});
    for (std::size_t k = 0; k < timeline_.failures.size(); ++k) {
      const auto& f = timeline_.failures[k];
      const bool recovery = f.kind == "recovered";
      const bool crash = is_crash(f);
      const cv::Scalar colour = recovery ? recovery_colour : crash ? crash_colour : link_colour;
      if (crash || recovery)
        for (int dash = title_px; dash < y; dash += 6)
          cv::line(image_, {x(f.t_s), dash}, {x(f.t_s), dash + 3}, colour, 1);
      if (crash)
        cross(x(f.t_s), middle);
      else
        cv::circle(image_, {x(f.t_s), middle}, 4, colour, cv::FILLED, cv::LINE_AA);
      // Labels alternate above and below the lane, so close faults stay readable.
      draw_text(image_, fault_label(f), {x(f.t_s) + 7, k % 2 == 0 ? middle - 4 : middle + 16}, 0.38,
                colour);
    }
  }

  void draw_axis() {
    const int y = chart_bottom_;
    cv::line(image_, {left_px, y}, {width_px - right_px, y}, ink, 1);
    const double step = round_tick_step(timeline_.end_s, 8);
    for (double t = 0.0; t <= timeline_.end_s + 1e-9; t += step) {
      cv::line(image_, {x(t), y}, {x(t), y + 5}, ink, 1);
      const std::string label = step < 1.0 ? fmt::format("{:.1f}", t) : fmt::format("{:.0f}", t);
      draw_text(image_, label, {x(t) - 8, y + 20}, 0.4);
    }
    draw_text(image_, "time (s)", {width_px - right_px - 60, y + 36}, 0.4);
  }

  const group_timeline& timeline_;
  cv::Mat image_;
  int chart_bottom_ = 0;
};

}  // namespace

std::vector<unsigned char> render_timeline(const group_timeline& timeline) {
  const cv::Mat image = timeline_painter(timeline).draw();
  std::vector<unsigned char> png;
  cv::imencode(".png", image, png);
  return png;
}

}  // namespace argus::report
