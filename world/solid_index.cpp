#include "world/solid_index.hpp"

#include <algorithm>
#include <cmath>

namespace argus::world {

bool inside_polygon(const std::vector<vec2>& polygon, const vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const vec2& a = polygon[i];
    const vec2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

solid_index::solid_index(const layout& plan, std::span<const service_counter* const> counters) {
  for (const auto& o : plan.obstacles) polygons_.push_back(o.polygon);
  for (const auto* c : counters) footprints_.push_back(c->footprint);
  width_ = static_cast<int>(std::ceil(plan.size_m.x() / cell_m)) + 1;
  height_ = static_cast<int>(std::ceil(plan.size_m.y() / cell_m)) + 1;
  std::vector<std::vector<std::uint32_t>> cells(static_cast<std::size_t>(width_ * height_));
  // Every cell a solid's bounding box touches, edges included: a point on the box's edge is
  // looked up in a cell that lists it. A box reaching past the plan is clamped to its edge cells;
  // points off the plan are tested against every solid (inside_solid).
  const auto add = [&](std::uint32_t solid, const vec2& lo, const vec2& hi) {
    const auto cell_of = [](double v, int n) {
      return std::clamp(static_cast<int>(std::floor(v / cell_m)), 0, n - 1);
    };
    for (int y = cell_of(lo.y(), height_); y <= cell_of(hi.y(), height_); ++y)
      for (int x = cell_of(lo.x(), width_); x <= cell_of(hi.x(), width_); ++x)
        cells[static_cast<std::size_t>(y * width_ + x)].push_back(solid);
  };
  for (std::uint32_t o = 0; o < polygons_.size(); ++o) {
    const auto& polygon = polygons_[o];
    if (polygon.empty()) continue;
    vec2 lo = polygon.front(), hi = polygon.front();
    for (const auto& v : polygon) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    add(o, lo, hi);
  }
  const auto polygons = static_cast<std::uint32_t>(polygons_.size());
  for (std::uint32_t f = 0; f < footprints_.size(); ++f)
    add(polygons + f, footprints_[f].min, footprints_[f].max);
  start_.assign(cells.size() + 1, 0);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    start_[c + 1] = start_[c] + static_cast<std::uint32_t>(cells[c].size());
    items_.insert(items_.end(), cells[c].begin(), cells[c].end());
  }
}

bool solid_index::inside(std::uint32_t solid, const vec2& p) const {
  const auto polygons = polygons_.size();
  if (solid < polygons) return inside_polygon(polygons_[solid], p);
  return footprints_[solid - polygons].contains(p);
}

bool solid_index::inside_solid(const vec2& p) const {
  if (width_ == 0) return false;
  const bool on_plan = p.x() >= 0.0 && p.y() >= 0.0 && p.x() < (width_ - 1) * cell_m &&
                       p.y() < (height_ - 1) * cell_m;
  if (!on_plan) {
    const auto all = static_cast<std::uint32_t>(polygons_.size() + footprints_.size());
    for (std::uint32_t s = 0; s < all; ++s)
      if (inside(s, p)) return true;
    return false;
  }
  const auto c = static_cast<std::size_t>(static_cast<int>(p.y() / cell_m) * width_ +
                                          static_cast<int>(p.x() / cell_m));
  for (auto i = start_[c]; i < start_[c + 1]; ++i)
    if (inside(items_[i], p)) return true;
  return false;
}

}  // namespace argus::world
