#include "eval/reachability.hpp"

#include <cmath>
#include <numbers>

#include "vision/emulated_sensor.hpp"
#include "world/station.hpp"

namespace argus::eval {
namespace {

constexpr double rad_per_deg = std::numbers::pi / 180.0;

// `angle` moved by whole turns as close as possible to `centre`.
double nearest_turn(double angle, double centre) {
  return angle - 360.0 * std::round((angle - centre) / 360.0);
}

}  // namespace

bool reachable(const config::camera_settings& camera, const world::station& station,
               const world::vec2& where, double height_m) {
  const world::vec2 base{camera.position.x_m, camera.position.y_m};
  const double ground = (where - base).norm();
  const double rise = height_m / 2.0 - camera.height_m;
  const double distance = std::hypot(ground, rise);
  if (distance < 1e-6) return false;
  const double aspect =
      static_cast<double>(camera.imaging.height_px) / static_cast<double>(camera.imaging.width_px);
  const double widest = camera.field_of_view_limits.max_deg;
  const double widest_vertical =
      2.0 * std::atan(std::tan(widest * rad_per_deg / 2.0) * aspect) / rad_per_deg;
  const double narrowest_vertical =
      2.0 * std::atan(std::tan(camera.field_of_view_limits.min_deg * rad_per_deg / 2.0) * aspect);
  const double tall_px =
      camera.imaging.height_px * height_m / (2.0 * distance * std::tan(narrowest_vertical / 2.0));
  if (tall_px < min_reachable_height_px) return false;
  const double tilt = std::atan2(rise, ground) / rad_per_deg;
  if (tilt < camera.tilt_limits.min_deg - widest_vertical / 2.0 ||
      tilt > camera.tilt_limits.max_deg + widest_vertical / 2.0)
    return false;
  const auto& pan_range = camera.pan_limits;
  if (pan_range.max_deg - pan_range.min_deg < 360.0) {
    const double centre = (pan_range.min_deg + pan_range.max_deg) / 2.0;
    const double pan =
        nearest_turn(std::atan2(where.y() - base.y(), where.x() - base.x()) / rad_per_deg, centre);
    if (pan < pan_range.min_deg - widest / 2.0 || pan > pan_range.max_deg + widest / 2.0)
      return false;
  }
  return vision::wall_free(station, base, where);
}

}  // namespace argus::eval
