#pragma once

// What a decoded plan view (world/plan_view.hpp) must show where the station, the cameras and
// the crowd put it: wall lines dark, camera dots red, each pedestrian's disc in her shirt
// colour and her trail behind her. Counts are kept rather than asserted pixel by pixel: later
// drawings (portals, labels, another pedestrian) may cover a few of them.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <opencv2/core.hpp>
#include <span>
#include <vector>

#include "config/scenario.hpp"
#include "world/plan_view.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::world {

/// How many of each thing the plan view should show, and how many it does show (walls: points
/// every metre along them).
struct plan_view_findings {
  int walls = 0, walls_drawn = 0;
  int cameras = 0, cameras_drawn = 0;
  int pedestrians = 0, pedestrians_drawn = 0;
  int trails = 0, trails_drawn = 0;

  /// Prints the counts, for the test log.
  void print() const {
    std::printf("[ plan     ] walls %d/%d, cameras %d/%d, pedestrians %d/%d, trails %d/%d\n",
                walls_drawn, walls, cameras_drawn, cameras, pedestrians_drawn, pedestrians,
                trails_drawn, trails);
  }
};

/// Looks at `image` (BGR, as cv::imread gives it) where `render_plan_view(where, cameras,
/// frame, trails, options)` draws each thing.
inline plan_view_findings inspect_plan_view(const cv::Mat& image, const station& where,
                                            std::span<const config::camera_settings> cameras,
                                            const snapshot& frame,
                                            const std::map<int, std::vector<vec2>>& trails,
                                            const plan_view_options& options = {}) {
  constexpr int margin_px = 24;  // as world/plan_view.cpp
  const double height_m = where.plan().size_m.y();
  const auto px = [&](const vec2& p) {
    return cv::Point(
        static_cast<int>(std::lround(margin_px + p.x() * options.pixels_per_m)),
        static_cast<int>(std::lround(margin_px + (height_m - p.y()) * options.pixels_per_m)));
  };
  const auto at = [&](const cv::Point& p) {
    return cv::Rect(0, 0, image.cols, image.rows).contains(p) ? image.at<cv::Vec3b>(p)
                                                              : cv::Vec3b(255, 255, 255);
  };
  const auto near = [](const cv::Vec3b& a, const cv::Vec3b& b, int tolerance) {
    for (int c = 0; c < 3; ++c)
      if (std::abs(int{a[c]} - int{b[c]}) > tolerance) return false;
    return true;
  };
  plan_view_findings f;
  // Walls: a dark line (20, 20, 20), wedges blended over it, at every metre along them (the
  // portals, drawn over the walls, and camera dots cover some).
  for (const auto& w : where.plan().walls) {
    for (std::size_t i = 1; i < w.points.size(); ++i) {
      const vec2 from = w.points[i - 1];
      const vec2 to = w.points[i];
      const int steps = std::max(1, static_cast<int>((to - from).norm()));
      for (int k = 0; k <= steps; ++k) {
        ++f.walls;
        const auto colour = at(px(from + (to - from) * (static_cast<double>(k) / steps)));
        if (colour[0] < 80 && colour[1] < 80 && colour[2] < 80) ++f.walls_drawn;
      }
    }
  }
  // Cameras: a red dot (BGR 0, 0, 200) at each camera's position.
  for (const auto& c : cameras) {
    ++f.cameras;
    if (near(at(px({c.position.x_m, c.position.y_m})), cv::Vec3b(0, 0, 200), 40)) ++f.cameras_drawn;
  }
  // Pedestrians: a disc in the shirt colour at each one's position; the middle point of her
  // trail (if at least 1.5 m behind her; an end of an anti-aliased line is drawn faint) in the
  // same colour, within a pixel.
  for (const auto& p : frame.pedestrians()) {
    const cv::Vec3b shirt(p.look.shirt.b, p.look.shirt.g, p.look.shirt.r);
    ++f.pedestrians;
    if (near(at(px(p.position)), shirt, 12)) ++f.pedestrians_drawn;
    const auto trail = trails.find(p.id);
    if (trail == trails.end() || trail->second.size() < 2) continue;
    const vec2 middle = trail->second[trail->second.size() / 2];
    if ((middle - p.position).norm() < 1.5) continue;
    ++f.trails;
    const cv::Point centre = px(middle);
    bool drawn = false;
    for (int dy = -1; dy <= 1 && !drawn; ++dy)
      for (int dx = -1; dx <= 1 && !drawn; ++dx)
        drawn = near(at(centre + cv::Point(dx, dy)), shirt, 40);
    if (drawn) ++f.trails_drawn;
  }
  return f;
}

}  // namespace argus::world
