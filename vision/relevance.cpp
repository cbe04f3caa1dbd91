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

double relevance(const ptz_state& required, const ptz_limits& limits,
                 const config::controller_settings& controller, camera_availability availability) {
  if (availability == camera_availability::busy) return 0.0;
  // eq. (1)
  return std::exp(
      -term(required.field_of_view_deg, limits.field_of_view, controller.relevance_sigma_fov_deg) -
      // A head that pans all the way round never runs out of pan: no leeway is lost, and the
      // mid-range of [-180, 180] would only measure a compass direction.
      (limits.pan_wraps()
           ? 0.0
           : term(required.pan_deg, limits.pan, controller.relevance_sigma_pan_deg)) -
      term(required.tilt_deg, limits.tilt, controller.relevance_sigma_tilt_deg));
}

}  // namespace argus::vision
