#pragma once
// A plot panel for the crowd benches' PNGs: data ranges mapped onto a rectangle of the image,
// with axes, ticks and labels.

#include <fmt/format.h>

#include <opencv2/core.hpp>
#include <string>

#include "report/drawing.hpp"

namespace argus::bench {

/// Data ranges mapped onto a rectangle of the image.
struct panel {
  cv::Rect box;
  double x_max;
  double y_max;
  cv::Point at(double x, double y) const {
    return {box.x + static_cast<int>(x / x_max * box.width),
            box.y + box.height - static_cast<int>(y / y_max * box.height)};
  }
  void axes(cv::Mat& image, const std::string& title, const std::string& x_label,
            const std::string& y_label, double x_step, double y_step) const {
    cv::rectangle(image, box, report::ink, 1);
    for (double x = 0.0; x <= x_max + 1e-9; x += x_step) {
      cv::line(image, at(x, 0), at(x, 0) + cv::Point(0, 4), report::ink);
      report::draw_text(image, fmt::format("{:g}", x), at(x, 0) + cv::Point(-8, 18), 0.38);
    }
    for (double y = 0.0; y <= y_max + 1e-9; y += y_step) {
      cv::line(image, at(0, y), at(0, y) - cv::Point(4, 0), report::ink);
      report::draw_text(image, fmt::format("{:g}", y), at(0, y) + cv::Point(-34, 5), 0.38);
    }
    report::draw_text(image, title, {box.x, box.y - 10}, 0.5);
    report::draw_text(image, x_label, {box.x + box.width / 2 - 60, box.y + box.height + 38}, 0.42);
    report::draw_text(image, y_label, {box.x - 40, box.y - 26}, 0.42);
  }
};

}  // namespace argus::bench
