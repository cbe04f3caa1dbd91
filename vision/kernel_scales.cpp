#include "vision/kernel_scales.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fmt/format.h"
#include "vision/multiscale_localizer.hpp"

namespace argus::vision {

std::vector<int> paper_scales(int frame_height_px, double divisor) {
  if (!(divisor > 0.0))
    throw std::invalid_argument(fmt::format("paper_scales: divisor must be > 0, not {}", divisor));
  std::vector<int> scales;
  for (int k = 1; k <= 10; ++k) {
    int l = static_cast<int>(std::lround(0.1 * k * frame_height_px / divisor));
    l = std::max(l, 1);
    if (scales.empty() || scales.back() != l) scales.push_back(l);
  }
  return scales;
}

double kernel_size_for(const cv::Size2d& size) {
  // (6l + 1)(2l + 1) = area, the positive root of 12 l^2 + 8 l + 1 - area = 0.
  const double area = std::max(size.area(), 1.0);
  return (std::sqrt(16.0 + 48.0 * area) - 8.0) / 24.0;
}

std::vector<int> target_scales(const cv::Size2d& size, int frame_height_px,
                               const scale_settings& settings) {
  if (!(settings.span >= 1.0) || settings.steps_per_octave < 1)
    throw std::invalid_argument(
        fmt::format("target_scales: span must be >= 1 and steps per octave >= 1, not {} and {}",
                    settings.span, settings.steps_per_octave));
  const int largest = std::max(1, (frame_height_px - 1) / 6);
  const int steps =
      static_cast<int>(std::lround(settings.steps_per_octave * std::log2(settings.span)));
  std::vector<int> scales;
  for (int k = -steps; k <= steps; ++k) {
    const double factor = std::exp2(static_cast<double>(k) / settings.steps_per_octave);
    const double l = kernel_size_for({size.width * factor, size.height * factor});
    scales.push_back(std::clamp(static_cast<int>(std::lround(l)), 1, largest));
  }
  scales.erase(std::unique(scales.begin(), scales.end()), scales.end());
  return scales;
}

std::vector<int> kernel_scales(const scale_settings& settings,
                               const std::optional<cv::Size2d>& target, int frame_height_px) {
  if (settings.rule == scale_rule::target && target && target->area() > 0.0)
    return target_scales(*target, frame_height_px, settings);
  return paper_scales(frame_height_px, settings.paper_divisor);
}

localizer_settings localizer_settings_for(const scale_settings& scales,
                                          const std::optional<cv::Size2d>& target,
                                          int frame_height_px, double rho, int max_regions) {
  const auto choice =
      scales.rule == scale_rule::target ? scale_choice::score : scale_choice::sharpness;
  return {kernel_scales(scales, target, frame_height_px), rho, max_regions, choice};
}

}  // namespace argus::vision
