#pragma once

#include <opencv2/core/mat.hpp>

#include "world/plan_view.hpp"

namespace argus::world {

/// render_plan_view's picture before it is encoded: BGR, 8 bits a channel. The run's report
/// draws over it (report/plan_report.cpp); taking it from the PNG cost a decode and an encode
/// more, of ten megapixels for the large station.
cv::Mat paint_plan_view(const station& where, std::span<const config::camera_settings> cameras,
                        const snapshot* frame, const std::map<int, std::vector<vec2>>* trails,
                        const plan_view_options& options = {});

}  // namespace argus::world
