#pragma once

// The station's solids (obstacles' polygons and counters' footprints) by the cells of a coarse
// grid that their bounding boxes touch. `station::walkable` asks whether a point is inside any
// solid once per navigation cell when a station loads: the large station's 777,600 cells
// against its 160 solids took most of its loading time (0.8 s of 1.5 s with its fields read from
// the cache), in the coordinator and again in every worker.

#include <cstdint>
#include <span>
#include <vector>

#include "world/layout.hpp"

namespace argus::world {

class solid_index {
 public:
  solid_index() = default;
  /// Holds its own copy of the solids' shapes: a copied station's index stands alone.
  solid_index(const layout& plan, std::span<const service_counter* const> counters);

  /// Whether `p` lies inside an obstacle's polygon or on a counter's footprint: the same answer
  /// as testing every one of them.
  bool inside_solid(const vec2& p) const;

 private:
  bool inside(std::uint32_t solid, const vec2& p) const;

  static constexpr double cell_m = 4.0;
  std::vector<std::vector<vec2>> polygons_;
  std::vector<box> footprints_;
  int width_ = 0;
  int height_ = 0;
  // Per cell, the solids whose bounding boxes touch it (CSR): a polygon's index, or the number
  // of polygons plus a footprint's.
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> items_;
};

/// Whether `p` is inside `polygon` (even-odd rule; a point on an edge may fall either way).
bool inside_polygon(const std::vector<vec2>& polygon, const vec2& p);

}  // namespace argus::world
