#include "report/drawing.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace argus::report {

cv::Scalar scalar_of(bgr colour) {
  return {static_cast<double>(colour.b), static_cast<double>(colour.g),
          static_cast<double>(colour.r)};
}

void draw_text(cv::Mat& image, const std::string& text, cv::Point at, double scale,
               const cv::Scalar& colour) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

int text_width(const std::string& text, double scale) {
  int baseline = 0;
  return cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline).width;
}

double round_tick_step(double span, int ticks) {
  const double raw = std::max(span, 1e-9) / ticks;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (raw <= m * power) return m * power;
  return 10.0 * power;
}

}  // namespace argus::report
