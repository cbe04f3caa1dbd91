#include "vision/scene_mesh.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <string_view>

namespace argus::vision {
namespace {

using vec3 = Eigen::Vector3d;
using rgb = std::array<float, 3>;

void push(std::vector<mesh_vertex>& out, const vec3& p, const vec3& n, const rgb& c,
          float pattern) {
  out.push_back({{static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())},
                 {static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())},
                 {c[0], c[1], c[2]},
                 pattern});
}

// Quad a-b-c-d (counter-clockwise seen from the side `n` points to), as two triangles.
void quad(std::vector<mesh_vertex>& out, const vec3& a, const vec3& b, const vec3& c, const vec3& d,
          const rgb& color, float pattern = 0.0f) {
  const vec3 n = (b - a).cross(d - a).normalized();
  for (const vec3* p : {&a, &b, &c, &a, &c, &d}) push(out, *p, n, color, pattern);
}

void floor_box(std::vector<mesh_vertex>& out, const world::box& b, const rgb& color,
               float pattern = 0.0f) {
  quad(out, {b.min.x(), b.min.y(), 0.0}, {b.max.x(), b.min.y(), 0.0}, {b.max.x(), b.max.y(), 0.0},
       {b.min.x(), b.max.y(), 0.0}, color, pattern);
}

// A prism over the convex or star-shaped polygon `outline` (fan from its centroid), from
// z = 0 to `height`.
void prism(std::vector<mesh_vertex>& out, const std::vector<world::vec2>& outline, double height,
           const rgb& side, const rgb& top) {
  const std::size_t n = outline.size();
  if (n < 3) return;
  world::vec2 centre{0.0, 0.0};
  for (const auto& p : outline) centre += p;
  centre /= static_cast<double>(n);
  // Orientation decides which way the side normals face.
  double area2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % n];
    area2 += a.x() * b.y() - b.x() * a.y();
  }
  for (std::size_t i = 0; i < n; ++i) {
    world::vec2 a = outline[i];
    world::vec2 b = outline[(i + 1) % n];
    if (area2 < 0.0) std::swap(a, b);
    quad(out, {a.x(), a.y(), 0.0}, {b.x(), b.y(), 0.0}, {b.x(), b.y(), height},
         {a.x(), a.y(), height}, side);
    const vec3 up{0.0, 0.0, 1.0};
    push(out, {centre.x(), centre.y(), height}, up, top, 0.0f);
    push(out, {a.x(), a.y(), height}, up, top, 0.0f);
    push(out, {b.x(), b.y(), height}, up, top, 0.0f);
  }
}

void box_prism(std::vector<mesh_vertex>& out, const world::box& b, double height, const rgb& side,
               const rgb& top) {
  prism(out, {b.min, {b.max.x(), b.min.y()}, b.max, {b.min.x(), b.max.y()}}, height, side, top);
}

// A slab `thickness` wide along segment a-b.
void slab(std::vector<mesh_vertex>& out, const world::vec2& a, const world::vec2& b,
          double thickness, double height, const rgb& side, const rgb& top) {
  const world::vec2 d = b - a;
  if (d.norm() < 1e-9) return;
  const world::vec2 n = world::vec2{-d.y(), d.x()}.normalized() * (thickness / 2.0);
  const world::vec2 e = d.normalized() * (thickness / 2.0);  // close the corners
  prism(out, {a - n - e, b - n + e, b + n + e, a + n - e}, height, side, top);
}

rgb region_color(world::region_kind kind) {
  switch (kind) {
    case world::region_kind::concourse:
      return {0.62f, 0.60f, 0.55f};
    case world::region_kind::waiting_room:
      return {0.72f, 0.66f, 0.56f};
    case world::region_kind::arcade:
      return {0.66f, 0.62f, 0.60f};
    case world::region_kind::platforms:
      return {0.50f, 0.50f, 0.50f};
    case world::region_kind::tracks:
      return {0.22f, 0.19f, 0.17f};
    case world::region_kind::other:
      return {0.55f, 0.55f, 0.55f};
  }
  return {0.55f, 0.55f, 0.55f};
}

bool starts_with(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

}  // namespace

scene_mesh build_scene_mesh(const world::layout& plan, const scene_heights& heights) {
  scene_mesh mesh;
  auto& floor = mesh.floor;
  // Outside the halls: dark ground, so that gaps read as "not station".
  floor_box(floor, {{-50.0, -50.0}, {plan.size_m.x() + 50.0, plan.size_m.y() + 50.0}},
            {0.16f, 0.16f, 0.17f});
  for (const auto& r : plan.regions) floor_box(floor, r.area, region_color(r.kind), 1.0f);
  for (const auto& p : plan.portals) {
    floor_box(
        floor, p.area,
        p.kind == world::portal_kind::street ? rgb{0.80f, 0.70f, 0.22f} : rgb{0.78f, 0.72f, 0.40f});
  }
  for (const auto& s : plan.stairways) {
    // Steps: alternating dark stripes across the long side.
    const world::vec2 size = s.area.max - s.area.min;
    const bool along_x = size.x() >= size.y();
    const double length = along_x ? size.x() : size.y();
    const int steps = std::max(2, static_cast<int>(length / 0.6));
    for (int k = 0; k < steps; ++k) {
      world::box step = s.area;
      const double a = length * k / steps;
      const double b = length * (k + 1) / steps;
      if (along_x) {
        step.min.x() = s.area.min.x() + a;
        step.max.x() = s.area.min.x() + b;
      } else {
        step.min.y() = s.area.min.y() + a;
        step.max.y() = s.area.min.y() + b;
      }
      floor_box(floor, step, k % 2 == 0 ? rgb{0.30f, 0.29f, 0.28f} : rgb{0.40f, 0.39f, 0.37f});
    }
  }
  for (const auto& m : plan.meeting_points) {
    // A floor medallion: an octagon.
    std::vector<world::vec2> ring;
    for (int k = 0; k < 8; ++k) {
      const double a = M_PI * k / 4.0;
      ring.push_back(m.position + 0.8 * world::vec2{std::cos(a), std::sin(a)});
    }
    for (int k = 0; k < 8; ++k) {
      const vec3 up{0.0, 0.0, 1.0};
      const rgb c{0.55f, 0.35f, 0.25f};
      push(floor, {m.position.x(), m.position.y(), 0.0}, up, c, 0.0f);
      push(floor, {ring[k].x(), ring[k].y(), 0.0}, up, c, 0.0f);
      push(floor, {ring[(k + 1) % 8].x(), ring[(k + 1) % 8].y(), 0.0}, up, c, 0.0f);
    }
  }

  auto& solids = mesh.solids;
  const rgb wall_side{0.80f, 0.76f, 0.68f};
  const rgb wall_top{0.55f, 0.52f, 0.48f};
  for (const auto& w : plan.walls) {
    for (std::size_t i = 0; i + 1 < w.points.size(); ++i) {
      slab(solids, w.points[i], w.points[i + 1], 0.3, heights.wall_m, wall_side, wall_top);
    }
  }
  for (const auto& o : plan.obstacles) {
    if (starts_with(o.name, "column")) {
      prism(solids, o.polygon, heights.column_m, {0.74f, 0.70f, 0.62f}, {0.6f, 0.6f, 0.6f});
    } else if (starts_with(o.name, "kiosk")) {
      prism(solids, o.polygon, heights.kiosk_m, {0.45f, 0.22f, 0.16f}, {0.85f, 0.80f, 0.70f});
    } else if (starts_with(o.name, "bench")) {
      prism(solids, o.polygon, heights.bench_m, {0.42f, 0.27f, 0.15f}, {0.52f, 0.34f, 0.19f});
    } else {
      prism(solids, o.polygon, heights.other_obstacle_m, {0.5f, 0.5f, 0.5f}, {0.6f, 0.6f, 0.6f});
    }
  }
  for (const auto& c : plan.ticket_booths) {
    box_prism(solids, c.footprint, heights.ticket_booth_m, {0.82f, 0.50f, 0.16f},
              {0.90f, 0.85f, 0.75f});
  }
  for (const auto& c : plan.vending_machines) {
    box_prism(solids, c.footprint, heights.vending_machine_m, {0.16f, 0.32f, 0.70f},
              {0.75f, 0.75f, 0.80f});
  }
  for (const auto& b : plan.benches) {
    slab(solids, b.from, b.to, 0.5, heights.bench_m, {0.42f, 0.27f, 0.15f}, {0.55f, 0.36f, 0.20f});
  }
  return mesh;
}

}  // namespace argus::vision
