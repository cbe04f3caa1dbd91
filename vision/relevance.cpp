#include "vision/relevance.hpp"

#include <cmath>

namespace argus::vision {
namespace {

// One term of eq. (1): (x - x̂)² / 2σ², with x̂ the mid-range; the difference taken the
// shorter way round when the axis `wraps`.
double term(double value, const config::degree_range& range, double sigma, bool wraps = false) {
  const double mid = (range.min_deg + range.max_deg) / 2.0;
  const double d = wraps ? std::remainder(value - mid, 360.0) : value - mid;
  return d * d / (2.0 * sigma * sigma);
}

}  // namespace

double relevance(const ptz_state& required, const ptz_limits& limits,
                 const config::controller_settings& controller, camera_availability availability) {
  if (availability == camera_availability::busy) return 0.0;
  // eq. (1)
  return std::exp(
      -term(required.field_of_view_deg, limits.field_of_view, controller.relevance_sigma_fov_deg) -
      term(required.pan_deg, limits.pan, controller.relevance_sigma_pan_deg, limits.pan_wraps()) -
      term(required.tilt_deg, limits.tilt, controller.relevance_sigma_tilt_deg));
}

}  // namespace argus::vision
