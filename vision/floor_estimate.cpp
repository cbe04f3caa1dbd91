#include "vision/floor_estimate.hpp"

namespace argus::vision {

std::optional<floor_estimate> floor_estimate_of(const camera_view& view, const cv::Rect2d& box,
                                                std::int64_t tick, const floor_rules& rules) {
  const bool feet = box.y + box.height < view.height_px - 1;
  const double plane = feet ? 0.0 : rules.assumed_height_m;
  const double v = feet ? box.y + box.height : box.y;
  const double drop = plane - view.placement.position_m.z();
  const auto at = [&](double dv) -> std::optional<Eigen::Vector2d> {
    const Eigen::Vector3d ray = view.back_project({box.x + box.width / 2.0, v + dv});
    // The plane must lie ahead along the ray, below (or above) the camera as the ray goes.
    if (ray.z() * drop <= 1e-9) return std::nullopt;
    const Eigen::Vector3d p = view.placement.position_m + (drop / ray.z()) * ray;
    return Eigen::Vector2d(p.x(), p.y());
  };
  const auto centre = at(0.0);
  if (!centre) return std::nullopt;
  const auto nearer = at(4.0);
  const auto farther = at(-4.0);
  // Near the horizon four pixels up may not meet the plane at all: the point is then as good
  // as unknown along the ray.
  constexpr double unknown_m = 10.0;
  const double spread = nearer && farther ? (*farther - *nearer).norm() / 2.0 : unknown_m;
  return floor_estimate{*centre, spread + (feet ? 0.0 : 0.3), tick};
}

bool confirmed_by(const std::optional<floor_estimate>& expected, bool first_of_task) {
  return expected ? expected->confirmed : first_of_task;
}

bool could_be(const floor_estimate& found, const floor_estimate& expected, double age_s,
              const floor_rules& rules) {
  return (found.where - expected.where).norm() <=
         expected.radius_m + found.radius_m + rules.walking_speed_mps * age_s + rules.slack_m;
}

}  // namespace argus::vision
