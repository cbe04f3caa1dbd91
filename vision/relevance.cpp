#include "vision/relevance.hpp"

#include <cmath>

namespace argus::vision {
namespace {

// One term of eq. (1): (x - x̂)² / 2σ², with x̂ the mid-range.
double term(double value, const config::degree_range& range, double sigma) {
  const double mid = (range.min_deg + range.max_deg) / 2.0;
  const double d = value - mid;
  return d * d / (2.0 * sigma * sigma);
}

}  // namespace

double relevance(const ptz_pose& required, const config::camera_settings& camera,
                 const config::controller_settings& controller, camera_availability availability) {
  if (availability == camera_availability::busy) return 0.0;
  // eq. (1)
  return std::exp(-term(required.field_of_view_deg, camera.field_of_view_limits,
                        controller.relevance_sigma_fov_deg) -
                  term(required.pan_deg, camera.pan_limits, controller.relevance_sigma_pan_deg) -
                  term(required.tilt_deg, camera.tilt_limits, controller.relevance_sigma_tilt_deg));
}

}  // namespace argus::vision
