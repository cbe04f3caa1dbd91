// The Voronoi method on hand-built crowds whose answer is known: lattices (each cell a square
// under the cut-off), someone alone (the cut-off polygon is the cell), someone on the area's
// edge (half of them counts), people at one point, people in single file, and a jittered
// crowd whose cells must tile the area.
#include "world/voronoi_measurement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "world/experiment_layouts.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::world {
namespace {

// The measurement does not look at the layout; any station can hold the snapshot.
const station& room() {
  static const station shared(bottleneck_room_layout(1.0));
  return shared;
}

snapshot frame_of(std::vector<pedestrian_state> people) {
  return snapshot(room(), 0, std::chrono::duration<double>{0.0}, std::move(people));
}

pedestrian_state walker(int id, vec2 at, vec2 velocity = {1.2, 0.0}) {
  pedestrian_state p;
  p.id = id;
  p.position = at;
  p.velocity = velocity;
  return p;
}

/// People on a square lattice `spacing_m` apart over [0, 12] x [0, 12], the first half a
/// spacing from the origin, all walking east at 1.2 m/s.
std::vector<pedestrian_state> lattice(double spacing_m) {
  std::vector<pedestrian_state> out;
  const int per_row = static_cast<int>(std::lround(12.0 / spacing_m));
  for (int row = 0; row < per_row; ++row) {
    for (int column = 0; column < per_row; ++column) {
      out.push_back(walker(static_cast<int>(out.size()) + 1,
                           {(column + 0.5) * spacing_m, (row + 0.5) * spacing_m}));
    }
  }
  return out;
}

/// Area of the 20-gon inscribed in the 1 m cut-off circle: (n / 2) r^2 sin(2 pi / n).
const double cut_off_m2 = 10.0 * std::sin(2.0 * std::numbers::pi / 20.0);

TEST(voronoi_measurement, half_metre_lattice_has_four_per_square_metre) {
  const auto frame = frame_of(lattice(0.5));
  // Cells 0.5 m x 0.5 m; one area's edges run along cell edges, the other's cut cells.
  for (const box& area : {box{{4.0, 4.0}, {6.0, 6.0}}, box{{4.1, 4.3}, {6.2, 5.9}}}) {
    const auto m = measure_area_voronoi(frame, area);
    EXPECT_NEAR(m.density_per_m2, 4.0, 1e-6);
    EXPECT_NEAR(m.speed_mps, 1.2, 1e-6);
    EXPECT_NEAR(m.specific_flow_per_m_s, 4.8, 1e-5);
  }
}

TEST(voronoi_measurement, metre_lattice_has_one_per_square_metre) {
  const auto frame = frame_of(lattice(1.0));
  for (const box& area : {box{{3.0, 3.0}, {7.0, 6.0}}, box{{3.3, 2.8}, {7.9, 5.1}}}) {
    const auto m = measure_area_voronoi(frame, area);
    EXPECT_NEAR(m.density_per_m2, 1.0, 1e-6);
    EXPECT_NEAR(m.speed_mps, 1.2, 1e-6);
    EXPECT_NEAR(m.specific_flow_per_m_s, 1.2, 1e-6);
  }
}

//   +-------------------+ y=8      M = 5 m x 4 m; the walker's cell is the whole
//   |      .-"-.        |          cut-off polygon, all of it in M: it counts once,
//   |     (  o  )       |          and the rest of M, nobody's, does not dilute its speed
//   |      '-.-'        |
//   +-------------------+ y=4
//  x=4                 x=9
TEST(voronoi_measurement, someone_alone_counts_once_with_the_cut_off_as_cell) {
  const box area{{4.0, 4.0}, {9.0, 8.0}};
  const auto m = measure_area_voronoi(frame_of({walker(1, {6.0, 6.0}, {1.2, 0.9})}), area);
  EXPECT_NEAR(m.density_per_m2, 1.0 / 20.0, 1e-9);
  EXPECT_NEAR(m.speed_mps, 1.5, 1e-9);
  EXPECT_NEAR(m.specific_flow_per_m_s, m.density_per_m2 * m.speed_mps, 1e-12);
}

TEST(voronoi_measurement, someone_on_the_edge_counts_half) {
  // On the area's west edge, the cut-off polygon (corners at 90 and 270 degrees) is halved.
  const box area{{4.0, 4.0}, {9.0, 8.0}};
  const auto m = measure_area_voronoi(frame_of({walker(1, {4.0, 6.0}, {1.2, 0.9})}), area);
  EXPECT_NEAR(m.density_per_m2, 0.5 / 20.0, 1e-9);
  EXPECT_NEAR(m.speed_mps, 1.5, 1e-9);
}

TEST(voronoi_measurement, nobody_near_the_area_gives_zeros) {
  const box area{{4.0, 4.0}, {6.0, 6.0}};
  for (const auto& people :
       {std::vector<pedestrian_state>{}, std::vector{walker(1, {2.9, 5.0}), walker(2, {9, 9})}}) {
    const auto m = measure_area_voronoi(frame_of(people), area);
    EXPECT_EQ(m.density_per_m2, 0.0);
    EXPECT_EQ(m.speed_mps, 0.0);
    EXPECT_EQ(m.specific_flow_per_m_s, 0.0);
  }
}

TEST(voronoi_measurement, people_at_one_point_share_its_cell) {
  const box alone{{4.0, 4.0}, {9.0, 8.0}};
  const auto pair = measure_area_voronoi(
      frame_of({walker(1, {6.0, 6.0}, {1.0, 0.0}), walker(2, {6.0, 6.0}, {2.0, 0.0})}), alone);
  EXPECT_NEAR(pair.density_per_m2, 2.0 / 20.0, 1e-9);
  EXPECT_NEAR(pair.speed_mps, 1.5, 1e-9);  // their mean speed

  // In a 1 m lattice, a second person standing still on a lattice point inside the area.
  auto people = lattice(1.0);
  people.push_back(walker(1000, {5.5, 4.5}, {0.0, 0.0}));
  const auto m = measure_area_voronoi(frame_of(people), {{3.0, 3.0}, {7.0, 6.0}});
  EXPECT_NEAR(m.density_per_m2, 13.0 / 12.0, 1e-6);
  EXPECT_NEAR(m.speed_mps, (11.0 * 1.2 + 0.6) / 12.0, 1e-6);
}

TEST(voronoi_measurement, single_file_cells_are_strips) {
  // People 0.5 m apart on y = 6: cells are strips 0.5 m wide, shorter than the area is tall.
  // Those at x = 4 and x = 8 are on the area's edges; seven between them count whole.
  std::vector<pedestrian_state> people;
  for (int k = 0; k <= 16; ++k) people.push_back(walker(k + 1, {2.0 + 0.5 * k, 6.0}));
  const auto m = measure_area_voronoi(frame_of(people), {{4.0, 5.0}, {8.0, 7.0}});
  EXPECT_NEAR(m.density_per_m2, 8.0 / 8.0, 1e-6);
}

TEST(voronoi_measurement, cells_are_cut_at_the_walls_given) {
  // Two files 0.5 m apart on y = 5.75 and 6.25 in a corridor 1 m wide (y = 5.5 to 6.5), 0.5 m
  // apart along it: 4 /m^2. Uncut, each file's cells reach past its wall to the cut-off, nearly
  // 1 m: the area, the corridor's width, holds under half of each cell.
  std::vector<pedestrian_state> people;
  int id = 1;
  for (int k = 0; k <= 16; ++k) {
    for (const double y : {5.75, 6.25}) people.push_back(walker(id++, {2.25 + 0.5 * k, y}));
  }
  const box area{{4.0, 5.5}, {8.0, 6.5}};
  const box corridor{{0.0, 5.5}, {12.0, 6.5}};
  const auto uncut = measure_area_voronoi(frame_of(people), area);
  EXPECT_LT(uncut.density_per_m2, 2.0);
  const auto cut = measure_area_voronoi(frame_of(people), area, voronoi_cut_off_m, corridor);
  EXPECT_NEAR(cut.density_per_m2, 4.0, 1e-6);
  EXPECT_NEAR(cut.speed_mps, 1.2, 1e-9);
}

TEST(voronoi_measurement, cells_of_a_dense_crowd_tile_the_area) {
  // A 0.5 m lattice with every person moved by up to 0.15 m: everyone's cell is under the
  // cut-off, nearly every four stand nearly on a circle, and the cells cover the area
  // exactly once, so with everyone at 1 m/s the Voronoi speed is 1.
  std::vector<pedestrian_state> people;
  for (int row = 0; row < 24; ++row) {
    for (int column = 0; column < 24; ++column) {
      const double k = row * 24.0 + column;
      const vec2 jitter{0.15 * std::sin(k * 12.9898), 0.15 * std::sin(k * 78.233)};
      people.push_back(walker(static_cast<int>(k) + 1,
                              vec2{(column + 0.5) * 0.5, (row + 0.5) * 0.5} + jitter, {0.6, 0.8}));
    }
  }
  const auto frame = frame_of(people);
  const box area{{3.7, 4.2}, {8.1, 7.3}};
  const auto m = measure_area_voronoi(frame, area);
  EXPECT_NEAR(m.speed_mps, 1.0, 1e-6);
  EXPECT_NEAR(m.density_per_m2, 4.0, 0.2);
  const auto again = measure_area_voronoi(frame, area);
  EXPECT_EQ(again.density_per_m2, m.density_per_m2);
  EXPECT_EQ(again.speed_mps, m.speed_mps);
}

/// The Voronoi-method measurement worked out without Subdiv2D and without choosing seeds:
/// each person's cut-off polygon clipped by the bisector with every other person (`people`
/// must not share a position).
voronoi_measurement by_every_bisector(const std::vector<pedestrian_state>& people,
                                      const box& area) {
  using polygon = std::vector<vec2>;
  const auto keep_left = [](const polygon& shape, const vec2& a, const vec2& b) {
    polygon out;
    const auto side = [&](const vec2& p) {
      return (b - a).x() * (p.y() - a.y()) - (b - a).y() * (p.x() - a.x());
    };
    for (std::size_t i = 0; i < shape.size(); ++i) {
      const vec2& p = shape[i];
      const vec2& q = shape[(i + 1) % shape.size()];
      if (side(p) >= 0.0) out.push_back(p);
      if ((side(p) >= 0.0) != (side(q) >= 0.0)) {
        out.push_back(p + (q - p) * (side(p) / (side(p) - side(q))));
      }
    }
    return out;
  };
  const auto area_of = [](const polygon& shape) {
    double twice = 0.0;
    for (std::size_t i = 0; i < shape.size(); ++i) {
      const vec2& q = shape[(i + 1) % shape.size()];
      twice += shape[i].x() * q.y() - shape[i].y() * q.x();
    }
    return std::abs(twice) / 2.0;
  };
  const polygon measured{
      area.min, {area.max.x(), area.min.y()}, area.max, {area.min.x(), area.max.y()}};
  const vec2 size = area.max - area.min;
  voronoi_measurement out;
  double covered_m2 = 0.0;
  for (const auto& p : people) {
    polygon cell;
    for (int k = 0; k < 20; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / 20.0;
      cell.push_back(p.position + vec2{std::cos(angle), std::sin(angle)});
    }
    for (const auto& other : people) {
      if (other.id == p.id) continue;
      const vec2 middle = (p.position + other.position) / 2.0;
      const vec2 away = other.position - p.position;
      cell = keep_left(cell, middle, middle + vec2{-away.y(), away.x()});
    }
    polygon inside = cell;
    for (std::size_t k = 0; k < measured.size(); ++k) {
      inside = keep_left(inside, measured[k], measured[(k + 1) % measured.size()]);
    }
    out.density_per_m2 += area_of(inside) / area_of(cell) / (size.x() * size.y());
    out.speed_mps += p.velocity.norm() * area_of(inside);
    covered_m2 += area_of(inside);
  }
  if (covered_m2 > 0.0) out.speed_mps /= covered_m2;
  return out;
}

TEST(voronoi_measurement, agrees_with_clipping_by_every_bisector) {
  // Random crowds, sparse to dense, here and at the far end of a large station: what
  // Subdiv2D's cells give for the people near the area is what every bisector gives.
  std::mt19937 random(7);
  for (const vec2& corner : {vec2{0.0, 0.0}, vec2{180.0, 70.0}}) {
    for (const int count : {3, 30, 150, 500}) {
      std::uniform_real_distribution<double> coordinate(0.0, 12.0);
      std::uniform_real_distribution<double> speed(0.0, 1.5);
      std::vector<pedestrian_state> people;
      for (int id = 1; id <= count; ++id) {
        people.push_back(walker(id, corner + vec2{coordinate(random), coordinate(random)},
                                {speed(random), speed(random)}));
      }
      const auto frame = frame_of(people);
      for (const box& area : {box{{4.0, 4.0}, {8.0, 8.0}}, box{{-1.0, 5.0}, {2.5, 12.5}},
                              box{{2.0, 3.0}, {11.0, 4.0}}}) {
        const box placed{corner + area.min, corner + area.max};
        const auto m = measure_area_voronoi(frame, placed);
        const auto expected = by_every_bisector(people, placed);
        EXPECT_NEAR(m.density_per_m2, expected.density_per_m2, 1e-5) << count;
        EXPECT_NEAR(m.speed_mps, expected.speed_mps, 1e-5) << count;
      }
    }
  }
}

TEST(voronoi_measurement, odd_crowds_give_finite_numbers) {
  // Everyone at one point; pairs a nanometre apart; a column in single file across the area.
  const box area{{4.0, 4.0}, {8.0, 8.0}};
  std::vector<pedestrian_state> people;
  for (int id = 1; id <= 50; ++id) people.push_back(walker(id, {6.0, 6.0}));
  const auto heap = measure_area_voronoi(frame_of(people), area);
  EXPECT_NEAR(heap.density_per_m2, 50.0 / 16.0, 1e-9);
  EXPECT_NEAR(heap.speed_mps, 1.2, 1e-9);
  people.clear();
  for (int k = 0; k < 40; ++k) {
    people.push_back(walker(2 * k + 1, {3.0 + 0.15 * k, 5.0}));
    people.push_back(walker(2 * k + 2, {3.0 + 0.15 * k + 1e-9, 5.0}));
    people.push_back(walker(100 + k, {6.5, 2.0 + 0.2 * k}));
  }
  const auto odd = measure_area_voronoi(frame_of(people), area);
  EXPECT_TRUE(std::isfinite(odd.density_per_m2) && odd.density_per_m2 > 0.0);
  EXPECT_TRUE(std::isfinite(odd.speed_mps) && odd.speed_mps > 0.0);
}

}  // namespace
}  // namespace argus::world
