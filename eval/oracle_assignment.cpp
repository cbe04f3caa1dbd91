#include "eval/oracle_assignment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "eval/reachability.hpp"
#include "world/snapshot.hpp"

namespace argus::eval {
namespace {

constexpr double deg = std::numbers::pi / 180.0;
// A camera keeps its task unless another is this much nearer.
constexpr double keep_factor = 0.75;
// The share of the frame's height the oracle gives its target.
constexpr double target_share = 1.0 / 3.0;

double distance_to(const config::camera_settings& c, const world::vec2& p) {
  return std::hypot(p.x() - c.position.x_m, p.y() - c.position.y_m);
}

}  // namespace

std::map<int, std::uint32_t> assign_cameras(const std::vector<config::camera_settings>& cameras,
                                            const std::set<int>& alive,
                                            const world::snapshot& frame,
                                            const world::station& station,
                                            const std::vector<oracle_target>& targets,
                                            const std::map<int, std::uint32_t>& previous) {
  std::map<int, std::uint32_t> out;
  std::vector<oracle_target> ordered = targets;
  std::sort(ordered.begin(), ordered.end(),
            [](const auto& a, const auto& b) { return a.task < b.task; });
  for (const auto& t : ordered) {
    const auto* who = frame.find(t.pedestrian);
    if (who == nullptr) continue;
    std::vector<std::pair<double, int>> candidates;  // (effective distance, camera)
    for (const auto& c : cameras) {
      if (alive.count(c.id) == 0 || out.count(c.id) != 0) continue;
      if (!reachable(c, station, who->position, who->look.height_m)) continue;
      double d = distance_to(c, who->position);
      if (auto p = previous.find(c.id); p != previous.end() && p->second == t.task)
        d *= keep_factor;
      candidates.emplace_back(d, c.id);
    }
    std::sort(candidates.begin(), candidates.end());
    for (std::size_t k = 0; k < candidates.size() && k < t.cameras; ++k)
      out[candidates[k].second] = t.task;
  }
  return out;
}

vision::ptz_state pose_towards(const config::camera_settings& camera, const world::vec2& where,
                               double height_m, bool zoom) {
  const auto limits = vision::ptz_limits::from(camera);
  const double dx = where.x() - camera.position.x_m;
  const double dy = where.y() - camera.position.y_m;
  const double ground = std::hypot(dx, dy);
  const double rise = height_m / 2.0 - camera.height_m;
  const double distance = std::max(0.5, std::hypot(ground, rise));
  const double aspect =
      static_cast<double>(camera.imaging.height_px) / static_cast<double>(camera.imaging.width_px);
  // Vertical field of view that makes her target_share of the frame, then horizontal.
  const double vertical = 2.0 * std::atan(height_m / (2.0 * distance * target_share));
  const double horizontal = 2.0 * std::atan(std::tan(vertical / 2.0) / aspect) / deg;
  double pan = std::atan2(dy, dx) / deg;
  if (!limits.pan_wraps()) {
    const double centre = (limits.pan.min_deg + limits.pan.max_deg) / 2.0;
    pan -= 360.0 * std::round((pan - centre) / 360.0);
  }
  vision::ptz_state wanted{pan, std::atan2(rise, ground) / deg,
                           zoom ? horizontal : camera.field_of_view_deg};
  return limits.clamp(wanted);
}

vision::ptz_state oracle_pose(const config::camera_settings& camera, const world::snapshot& frame,
                              int pedestrian, bool zoom) {
  const auto* who = frame.find(pedestrian);
  if (who == nullptr) return {camera.pan_deg, camera.tilt_deg, camera.field_of_view_deg};
  return pose_towards(camera, who->position, who->look.height_m, zoom);
}

}  // namespace argus::eval
