#include "world/voronoi_measurement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <vector>

#include "world/snapshot.hpp"

namespace argus::world {
namespace {

using polygon = std::vector<vec2>;

// More edges change the cut-off cells' area by little (a 20-gon has 98.4 % of the circle's),
// and the polygon's corners lie on the circle as in jpsreport.
constexpr int cut_off_edges = 20;

/// The part of the convex polygon `shape` on the left of the line from `a` to `b`.
polygon clip_left_of(const polygon& shape, const vec2& a, const vec2& b) {
  const vec2 direction = b - a;
  const auto side = [&](const vec2& p) {
    return direction.x() * (p.y() - a.y()) - direction.y() * (p.x() - a.x());
  };
  polygon out;
  for (std::size_t i = 0; i < shape.size(); ++i) {
    const vec2& p = shape[i];
    const vec2& q = shape[(i + 1) % shape.size()];
    const double side_p = side(p);
    const double side_q = side(q);
    if (side_p >= 0.0) out.push_back(p);
    if ((side_p >= 0.0) != (side_q >= 0.0))
      out.push_back(p + (q - p) * (side_p / (side_p - side_q)));
  }
  return out;
}

/// `shape` ∩ `convex`, both convex, `convex` counter-clockwise (Sutherland-Hodgman). Not
/// cv::intersectConvexConvex: it goes wrong on polygons with nearly coincident corners
/// (opencv/opencv#22812, open; reproduced on 4.6), and Subdiv2D's facets have them wherever
/// four people stand nearly on a circle. With crowds on a square lattice, everyone moved by
/// up to 1 um (1 cm), it got 6 % (0.03 %) of the cells' parts of a box wrong, e.g. 5.1 m^2 for
/// 0.004 m^2, where clipping by half-planes in double added up to the box every time.
polygon clip(polygon shape, const polygon& convex) {
  for (std::size_t i = 0; i < convex.size() && !shape.empty(); ++i) {
    shape = clip_left_of(shape, convex[i], convex[(i + 1) % convex.size()]);
  }
  return shape;
}

double area_of(const polygon& shape) {
  double twice = 0.0;
  for (std::size_t i = 0; i < shape.size(); ++i) {
    const vec2& p = shape[i];
    const vec2& q = shape[(i + 1) % shape.size()];
    twice += p.x() * q.y() - p.y() * q.x();
  }
  return std::abs(twice) / 2.0;
}

polygon cut_off_polygon(const vec2& centre, double radius_m) {
  polygon out;
  for (int k = 0; k < cut_off_edges; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / cut_off_edges;
    out.push_back(centre + radius_m * vec2{std::cos(angle), std::sin(angle)});
  }
  return out;
}

box grown(const box& b, double by_m) {
  return {b.min - vec2{by_m, by_m}, b.max + vec2{by_m, by_m}};
}

}  // namespace

voronoi_measurement measure_area_voronoi(const snapshot& frame, const box& area,
                                         double cut_off_radius_m,
                                         const std::optional<box>& within) {
  voronoi_measurement out;
  const vec2 size = area.max - area.min;
  const double area_m2 = size.x() * size.y();
  const double r = cut_off_radius_m;
  if (area_m2 <= 0.0 || r <= 0.0) return out;
  // Subdiv2D works in float: coordinates relative to the area's centre keep its rounding
  // at a tenth of a micrometre instead of ten micrometres at the far end of the station.
  const vec2 origin = area.center();
  // A cell lies within r of its owner, so only people within r of M have a cell reaching
  // into it. Within r of such a person the cell is decided by neighbours within 2 r of them:
  // the bisector with anyone farther lies beyond r. So everyone within 3 r of M is a seed,
  // and the rest of the station does not matter.
  const box seeds_from = grown(area, 3.0 * r);
  const box cells_from = grown(area, r);
  std::vector<vec2> seeds;
  std::vector<double> speeds;
  std::vector<bool> reaches;
  for (const auto& p : frame.pedestrians()) {
    if (!seeds_from.contains(p.position)) continue;
    seeds.push_back(p.position - origin);
    speeds.push_back(p.velocity.norm());
    reaches.push_back(cells_from.contains(p.position));
  }
  if (std::find(reaches.begin(), reaches.end(), true) == reaches.end()) return out;

  // Subdiv2D's outer triangle has its corners at least 2 S from any point of its rectangle (S
  // the longer side), so their bisectors pass S away: with S > r they cut no cut-off cell.
  vec2 low = seeds.front();
  vec2 high = seeds.front();
  for (const auto& s : seeds) {
    low = low.cwiseMin(s);
    high = high.cwiseMax(s);
  }
  const int x0 = static_cast<int>(std::floor(low.x() - r));
  const int y0 = static_cast<int>(std::floor(low.y() - r));
  const int x1 = static_cast<int>(std::ceil(high.x() + r)) + 1;  // the far edge is excluded
  const int y1 = static_cast<int>(std::ceil(high.y() + r)) + 1;
  cv::Subdiv2D subdivision(cv::Rect(x0, y0, x1 - x0, y1 - y0));
  // insert() answers a point already there (or within FLT_EPSILON of one) with that vertex:
  // people at one point become one seed, and share its cell below.
  std::vector<std::vector<std::size_t>> members;
  std::vector<int> vertices;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    const auto vertex = static_cast<std::size_t>(subdivision.insert(
        cv::Point2f(static_cast<float>(seeds[i].x()), static_cast<float>(seeds[i].y()))));
    if (vertex >= members.size()) members.resize(vertex + 1);
    if (members[vertex].empty() && reaches[i]) vertices.push_back(static_cast<int>(vertex));
    members[vertex].push_back(i);
  }
  std::vector<std::vector<cv::Point2f>> facets;
  std::vector<cv::Point2f> centres;
  subdivision.getVoronoiFacetList(vertices, facets, centres);

  const polygon measured{area.min - origin,
                         {area.max.x() - origin.x(), area.min.y() - origin.y()},
                         area.max - origin,
                         {area.min.x() - origin.x(), area.max.y() - origin.y()}};
  polygon walkable;
  if (within) {
    walkable = {within->min - origin,
                {within->max.x() - origin.x(), within->min.y() - origin.y()},
                within->max - origin,
                {within->min.x() - origin.x(), within->max.y() - origin.y()}};
  }
  double density_sum = 0.0;
  double speed_sum = 0.0;
  double covered_m2 = 0.0;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const auto& group = members[static_cast<std::size_t>(vertices[k])];
    polygon facet;
    for (const auto& corner : facets[k]) facet.push_back({corner.x, corner.y});
    polygon cell = clip(std::move(facet), cut_off_polygon(seeds[group.front()], r));
    if (within) cell = clip(std::move(cell), walkable);
    const double cell_m2 = area_of(cell);
    if (cell_m2 <= 0.0) continue;
    const double inside_m2 = area_of(clip(cell, measured));
    // k people at one point: each owns 1/k of the cell, so each adds the same fraction to
    // the density, and the cell's speed is their mean speed.
    double group_speed_sum = 0.0;
    for (const auto i : group) group_speed_sum += speeds[i];
    density_sum += static_cast<double>(group.size()) * inside_m2 / cell_m2;
    speed_sum += group_speed_sum / static_cast<double>(group.size()) * inside_m2;
    covered_m2 += inside_m2;
  }
  out.density_per_m2 = density_sum / area_m2;
  out.speed_mps = covered_m2 > 0.0 ? speed_sum / covered_m2 : 0.0;
  out.specific_flow_per_m_s = out.density_per_m2 * out.speed_mps;
  return out;
}

}  // namespace argus::world
