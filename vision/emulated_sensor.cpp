#include "vision/emulated_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "config/derive_seed.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::vision {
namespace {

double logistic(double z) {
  return 1.0 / (1.0 + std::exp(-z));
}

// Occlusion sampling grid (columns x rows) over a box: a figure is tall, so more rows.
constexpr int grid_columns = 6;
constexpr int grid_rows = 18;

}  // namespace

// station::line_clear looks only at segments near its start, so a long line is checked in
// pieces shorter than that reach.
bool wall_free(const world::station& where, const world::vec2& a, const world::vec2& b) {
  const double length = (b - a).norm();
  const double piece = 0.9 * world::station::segment_reach_m;
  const int pieces = std::max(1, static_cast<int>(std::ceil(length / piece)));
  world::vec2 from = a;
  for (int k = 1; k <= pieces; ++k) {
    const world::vec2 to = a + (b - a) * (static_cast<double>(k) / pieces);
    if (!where.line_clear(from, to)) return false;
    from = to;
  }
  return true;
}

color_histogram appearance_signature(const world::appearance& look, const histogram_bins& bins) {
  // Share of a standing figure's visible area (trousers include legs, shirt includes arms).
  const std::pair<world::rgb8, int> parts[] = {
      {look.shirt, 40}, {look.trousers, 42}, {look.skin, 10}, {look.hair, 8}};
  const double shading[] = {1.0, 0.8, 0.6};
  cv::Mat strip(1, 100 * 3, CV_8UC3);
  int x = 0;
  for (const double shade : shading)
    for (const auto& [colour, share] : parts)
      for (int k = 0; k < share; ++k, ++x)
        strip.at<cv::Vec3b>(0, x) = cv::Vec3b(cv::saturate_cast<std::uint8_t>(colour.b * shade),
                                              cv::saturate_cast<std::uint8_t>(colour.g * shade),
                                              cv::saturate_cast<std::uint8_t>(colour.r * shade));
  return color_histogram::of_image(strip, bins);
}

std::vector<pedestrian_view> visible_pedestrians(const world::snapshot& frame,
                                                 const world::station& where,
                                                 const camera_view& view) {
  std::vector<pedestrian_view> seen;
  // The pose's trigonometry once per frame, not once per projected point.
  const camera_projection projection(view);
  const Eigen::Vector3d forward = projection.forward();
  const Eigen::Vector3d& camera = view.placement.position_m;
  const double focal = projection.focal_px();
  const cv::Rect2d image(0.0, 0.0, view.width_px, view.height_px);
  for (const auto& who : frame.pedestrians()) {
    const Eigen::Vector3d foot(who.position.x(), who.position.y(), 0.0);
    const Eigen::Vector3d head(who.position.x(), who.position.y(), who.look.height_m);
    const double depth = forward.dot(0.5 * (foot + head) - camera);
    // Points nearer than the renderer's near plane are clipped away, not seen.
    if (forward.dot(foot - camera) < 0.25 || forward.dot(head - camera) < 0.25) continue;
    const auto foot_px = projection.project(foot);
    const auto head_px = projection.project(head);
    if (!foot_px || !head_px) continue;
    const double width = who.look.girth_m * focal / depth;
    const double top = std::min(head_px->y(), foot_px->y());
    const double height = std::abs(foot_px->y() - head_px->y());
    const double centre_u = 0.5 * (foot_px->x() + head_px->x());
    const cv::Rect2d box(centre_u - width / 2.0, top, width, std::max(height, 1.0));
    if ((box & image).area() <= 0.0) continue;
    if (!wall_free(where, camera.head<2>(), who.position)) continue;
    seen.push_back({who.id, box, depth, 0.0});
  }
  std::sort(seen.begin(), seen.end(),
            [](const auto& a, const auto& b) { return a.depth_m < b.depth_m; });
  // Only a nearer box that overlaps hers can hide a point of hers: in a crowded view testing
  // every sample against every nearer box cost a third of a large station's run.
  std::vector<const cv::Rect2d*> in_front;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    auto& me = seen[i];
    in_front.clear();
    for (std::size_t j = 0; j < i; ++j)
      if ((seen[j].box & me.box).area() > 0.0) in_front.push_back(&seen[j].box);
    int hidden = 0;
    for (int r = 0; r < grid_rows; ++r)
      for (int c = 0; c < grid_columns; ++c) {
        const cv::Point2d p(me.box.x + (c + 0.5) * me.box.width / grid_columns,
                            me.box.y + (r + 0.5) * me.box.height / grid_rows);
        bool covered = !image.contains(p);
        for (std::size_t j = 0; j < in_front.size() && !covered; ++j)
          covered = in_front[j]->contains(p);
        hidden += covered ? 1 : 0;
      }
    me.occlusion = static_cast<double>(hidden) / (grid_rows * grid_columns);
  }
  return seen;
}

emulated_sensor::emulated_sensor(sensor_model model, std::uint64_t seed, histogram_bins bins)
    : model_(model), bins_(bins), random_(seed) {
  // nop
}

emulated_sensor emulated_sensor::for_camera(sensor_model model, std::uint64_t run_seed,
                                            int camera_id) {
  return emulated_sensor(model,
                         config::derive_seed(run_seed, static_cast<std::uint64_t>(camera_id)));
}

double emulated_sensor::miss_probability(double occlusion, double height_px) const {
  if (occlusion > model_.max_occlusion || height_px < model_.min_height_px) return 1.0;
  return logistic(model_.miss_bias + model_.miss_per_occlusion * occlusion +
                  model_.miss_per_log_height * std::log(std::max(height_px, 1.0)));
}

double emulated_sensor::confusion_probability(double similarity) const {
  return logistic(model_.confusion_bias + model_.confusion_per_similarity * similarity);
}

// Box-Muller: world::rng has no normal distribution, and std::normal_distribution differs
// between standard libraries.
double emulated_sensor::normal() noexcept {
  const double u = std::max(random_.uniform(), 1e-300);
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * random_.uniform());
}

const color_histogram& emulated_sensor::signature_of(const world::pedestrian_state& who) {
  for (const auto& [look, signature] : signatures_)
    if (look == who.look) return signature;
  signatures_.emplace_back(who.look, appearance_signature(who.look, bins_));
  return signatures_.back().second;
}

sensor_detection emulated_sensor::make_detection(const pedestrian_view& seen,
                                                 const world::snapshot& frame,
                                                 const camera_view& view) {
  const double sigma = model_.box_sigma * seen.box.height;
  const double cx = seen.box.x + seen.box.width / 2.0 + sigma * normal();
  const double cy = seen.box.y + seen.box.height / 2.0 + sigma * normal();
  const double w = std::max(1.0, seen.box.width + sigma * normal());
  const double h = std::max(1.0, seen.box.height + sigma * normal());
  const cv::Rect box =
      cv::Rect(static_cast<int>(std::lround(cx - w / 2.0)),
               static_cast<int>(std::lround(cy - h / 2.0)), static_cast<int>(std::lround(w)),
               static_cast<int>(std::lround(h))) &
      cv::Rect(0, 0, view.width_px, view.height_px);
  const auto* who = frame.find(seen.id);
  return {box, signature_of(*who),
          std::clamp(model_.confidence_unoccluded * (1.0 - seen.occlusion), 0.0, 1.0), seen.id};
}

std::vector<sensor_detection> emulated_sensor::detect(const world::snapshot& frame,
                                                      const world::station& where,
                                                      const camera_view& view) {
  std::vector<sensor_detection> found;
  for (const auto& seen : visible_pedestrians(frame, where, view)) {
    // One draw per visible pedestrian whatever the outcome, so the stream stays aligned.
    const bool missed = random_.uniform() < miss_probability(seen.occlusion, seen.box.height);
    if (!missed) found.push_back(make_detection(seen, frame, view));
  }
  return found;
}

sensor_observation emulated_sensor::look_for(int target_id, const world::snapshot& frame,
                                             const world::station& where, const camera_view& view) {
  return look_for(target_id, frame, visible_pedestrians(frame, where, view), view);
}

sensor_observation emulated_sensor::look_for(int target_id, const world::snapshot& frame,
                                             std::span<const pedestrian_view> seen,
                                             const camera_view& view) {
  sensor_observation result;
  const auto target =
      std::find_if(seen.begin(), seen.end(), [&](const auto& v) { return v.id == target_id; });
  const double miss_draw = random_.uniform();
  const double confusion_draw = random_.uniform();
  if (target == seen.end()) return result;
  if (miss_draw < miss_probability(target->occlusion, target->box.height)) return result;
  const auto& target_signature = signature_of(*frame.find(target_id));
  const pedestrian_view* twin = nullptr;
  double similarity = 0.0;
  for (const auto& other : seen) {
    if (other.id == target_id || other.occlusion > model_.max_occlusion) continue;
    const double s = normalized_intersection(target_signature, signature_of(*frame.find(other.id)));
    if (s > similarity) {
      similarity = s;
      twin = &other;
    }
  }
  result.found = true;
  if (twin != nullptr && confusion_draw < confusion_probability(similarity)) {
    result.detection = make_detection(*twin, frame, view);
    result.confused = true;
  } else {
    result.detection = make_detection(*target, frame, view);
  }
  return result;
}

}  // namespace argus::vision
