#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "report/camera_colours.hpp"

namespace argus::report {

// Shared by the report's pictures (internal to argus_report: the header needs OpenCV).

/// The colour of text, axes and outlines.
inline const cv::Scalar ink(30, 30, 30);

/// `colour` as OpenCV takes it.
cv::Scalar scalar_of(bgr colour);

/// Writes `text` with its baseline's left end at `at`, in the report's font.
void draw_text(cv::Mat& image, const std::string& text, cv::Point at, double scale = 0.42,
               const cv::Scalar& colour = ink);

/// How wide draw_text writes `text` at `scale`, in pixels.
int text_width(const std::string& text, double scale);

/// A round axis step (1, 2 or 5 times a power of ten) giving about `ticks` ticks over `span`.
double round_tick_step(double span, int ticks);

}  // namespace argus::report
