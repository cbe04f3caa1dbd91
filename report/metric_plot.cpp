#include "report/metric_plot.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "fmt/format.h"
#include "report/drawing.hpp"

namespace argus::report {

namespace {

constexpr int width_px = 720;
constexpr int height_px = 460;
constexpr int left_px = 80;
constexpr int right_px = 30;
constexpr int top_px = 44;
constexpr int bottom_px = 70;
const cv::Scalar line_colour(180, 100, 30);
const cv::Scalar grid_colour(230, 230, 230);

std::optional<double> number_of(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

// Five or so round ticks covering [low, high].
std::vector<double> ticks_over(double low, double high) {
  const double step = round_tick_step(high - low, 5);
  std::vector<double> out;
  for (double t = std::ceil(low / step) * step; t <= high + step * 1e-9; t += step)
    out.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  return out;
}

}  // namespace

std::vector<unsigned char> render_metric_plot(const std::string& title,
                                              const std::string& parameter,
                                              const std::vector<metric_point>& all_points) {
  std::vector<metric_point> points;
  for (const auto& p : all_points)
    if (p.metric.count > 0) points.push_back(p);
  cv::Mat image(height_px, width_px, CV_8UC3, cv::Scalar(255, 255, 255));
  draw_text(image, title, {left_px, 26}, 0.55);
  const int plot_w = width_px - left_px - right_px;
  const int plot_h = height_px - top_px - bottom_px;
  cv::rectangle(image, {left_px, top_px}, {left_px + plot_w, top_px + plot_h}, ink, 1);

  // x positions: numeric when every value is a number, else categories evenly spaced.
  std::vector<double> xs;
  bool numeric = !points.empty();
  for (const auto& p : points) {
    const auto v = number_of(p.value);
    numeric = numeric && v.has_value();
    xs.push_back(v.value_or(0.0));
  }
  if (!numeric)
    for (std::size_t k = 0; k < points.size(); ++k) xs[k] = static_cast<double>(k);
  double x_low = xs.empty() ? 0.0 : *std::min_element(xs.begin(), xs.end());
  double x_high = xs.empty() ? 1.0 : *std::max_element(xs.begin(), xs.end());
  const double x_pad = x_high > x_low ? 0.08 * (x_high - x_low) : 0.5;
  x_low -= x_pad;
  x_high += x_pad;

  double y_low = HUGE_VAL;
  double y_high = -HUGE_VAL;
  for (const auto& p : points) {
    const double half = p.metric.half_width.value_or(0.0);
    y_low = std::min(y_low, p.metric.mean - half);
    y_high = std::max(y_high, p.metric.mean + half);
  }
  if (points.empty()) {
    y_low = 0.0;
    y_high = 1.0;
  }
  if (y_high - y_low < 1e-12) {
    const double pad = std::max(std::abs(y_high) * 0.1, 0.5);
    y_low -= pad;
    y_high += pad;
  }
  const double y_pad = 0.08 * (y_high - y_low);
  y_low -= y_pad;
  y_high += y_pad;

  auto px = [&](double x, double y) {
    return cv::Point(
        left_px + static_cast<int>(std::lround(plot_w * (x - x_low) / (x_high - x_low))),
        top_px + static_cast<int>(std::lround(plot_h * (y_high - y) / (y_high - y_low))));
  };

  for (double t : ticks_over(y_low, y_high)) {
    const cv::Point at = px(x_low, t);
    cv::line(image, at, {left_px + plot_w, at.y}, grid_colour, 1);
    const std::string label = fmt::format("{:.4g}", t);
    draw_text(image, label, {left_px - 8 - text_width(label, 0.42), at.y + 5});
  }
  const auto x_ticks = numeric ? ticks_over(x_low, x_high) : xs;
  for (std::size_t k = 0; k < x_ticks.size(); ++k) {
    const cv::Point at = px(x_ticks[k], y_low);
    cv::line(image, at, at + cv::Point(0, 5), ink, 1);
    const std::string label = numeric ? fmt::format("{:.4g}", x_ticks[k]) : points[k].value;
    draw_text(image, label, {at.x - text_width(label, 0.42) / 2, at.y + 22});
  }
  draw_text(image, parameter,
            {left_px + plot_w / 2 - text_width(parameter, 0.5) / 2, height_px - 16}, 0.5);

  if (points.empty()) draw_text(image, "no runs with this metric", {left_px + 20, top_px + 30});
  for (std::size_t k = 1; k < points.size(); ++k)
    cv::line(image, px(xs[k - 1], points[k - 1].metric.mean), px(xs[k], points[k].metric.mean),
             line_colour, 2, cv::LINE_AA);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto& m = points[k].metric;
    if (m.half_width) {
      const cv::Point low = px(xs[k], m.mean - *m.half_width);
      const cv::Point high = px(xs[k], m.mean + *m.half_width);
      cv::line(image, low, high, ink, 1, cv::LINE_AA);
      cv::line(image, low - cv::Point(6, 0), low + cv::Point(6, 0), ink, 1);
      cv::line(image, high - cv::Point(6, 0), high + cv::Point(6, 0), ink, 1);
    }
    cv::circle(image, px(xs[k], m.mean), 4, line_colour, cv::FILLED, cv::LINE_AA);
    draw_text(image, fmt::format("n={}", m.count), px(xs[k], m.mean) + cv::Point(7, -6), 0.35);
  }
  std::vector<unsigned char> png;
  cv::imencode(".png", image, png);
  return png;
}

}  // namespace argus::report
