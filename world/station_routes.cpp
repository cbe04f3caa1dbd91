// The station's route queries: walking distance and the way to walk, read off a target's
// distance field between the navigation grid's cell centres.

#include <array>
#include <cmath>
#include <limits>

#include "world/station.hpp"

namespace argus::world {

namespace {

constexpr float unreachable = std::numeric_limits<float>::infinity();

/// The grid direction (station's 8-neighbour numbering: 0 = +x, counter-clockwise) of a step.
constexpr int direction_of(int dx, int dy) {
  constexpr int table[3][3] = {{5, 6, 7}, {4, -1, 0}, {3, 2, 1}};
  return table[dy + 1][dx + 1];
}

/// edge_towards[a][b]: the bit of the grid edge from stencil corner a to corner b (corner k
/// is cell (x0 + k % 2, y0 + k / 2)), none from a corner to itself.
constexpr auto edge_towards = [] {
  std::array<std::array<unsigned, 4>, 4> bits{};
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      if (a != b) bits[a][b] = 1u << direction_of(b % 2 - a % 2, b / 2 - a / 2);
    }
  }
  return bits;
}();

}  // namespace

float station::field_at(int field, int cx, int cy) const {
  if (cx < 0 || cy < 0 || cx >= grid_w_ || cy >= grid_h_) return unreachable;
  return fields_[field][cy * grid_w_ + cx];
}

double station::distance_to(int field, const vec2& p) const {
  const int c = cell_index(p);
  const int cx = c % grid_w_;
  const int cy = c / grid_w_;
  // Beside a wall a cell counts only if it is in sight; a cell no lower than the best so far
  // cannot beat it (the walk to it adds to v), so its sight is not tested. In the open all
  // nine count and nothing branches on their values, which go either way at random
  // (unreachable cells are infinite and never win).
  const bool beside_wall = near_wall_[c] != 0;
  double best = std::numeric_limits<double>::infinity();
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const double v = field_at(field, cx + dx, cy + dy);
      const vec2 centre{(cx + dx + 0.5) * settings_.cell_m, (cy + dy + 0.5) * settings_.cell_m};
      if (beside_wall && (v >= best || !line_clear(p, centre))) continue;
      best = std::min(best, v + (centre - p).norm());
    }
  }
  return best;
}

std::pair<int, int> station::stencil_corner(const vec2& p) const {
  return {static_cast<int>(std::floor(p.x() / settings_.cell_m - 0.5)),
          static_cast<int>(std::floor(p.y() / settings_.cell_m - 0.5))};
}

void station::prefetch_route(int field, const vec2& p) const {
  if (field < 0) return;
  // direction_to's 4 x 4 patch (distance_to's 3 x 3 cells lie inside it); a row of it may
  // straddle two cache lines.
  const auto [x0, y0] = stencil_corner(p);
  const int x = x0 - 1;
  const int y = y0 - 1;
  if (x < 0 || y < 0 || x + 3 >= grid_w_ || y + 3 >= grid_h_) return;
  const float* row = fields_[field].data() + y * grid_w_ + x;
  for (int j = 0; j < 4; ++j, row += grid_w_) {
    __builtin_prefetch(row);
    __builtin_prefetch(row + 3);
  }
}

vec2 station::direction_to(int field, const vec2& p) const {
  const double cell = settings_.cell_m;
  // Bilinear interpolation between the four surrounding cell centres gives a smooth route
  // direction instead of the grid's eight compass directions.
  const auto [x0, y0] = stencil_corner(p);
  const double tx = p.x() / cell - 0.5 - x0;
  const double ty = p.y() / cell - 0.5 - y0;
  // The field on the 4 x 4 cells around the stencil, patch[j][i] = cell (x0 - 1 + i, y0 - 1 + j),
  // read in one go before anything depends on it: the four rows are four cache lines of a large
  // array, and loads issued together miss together instead of one after another.
  float patch[4][4];
  if (x0 >= 1 && y0 >= 1 && x0 + 2 < grid_w_ && y0 + 2 < grid_h_) {
    const float* row = fields_[field].data() + (y0 - 1) * grid_w_ + (x0 - 1);
    for (int j = 0; j < 4; ++j, row += grid_w_) {
      for (int i = 0; i < 4; ++i) patch[j][i] = row[i];
    }
  } else {
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) patch[j][i] = field_at(field, x0 - 1 + i, y0 - 1 + j);
    }
  }
  // Corner k of the stencil is cell (x0 + k % 2, y0 + k / 2).
  double f[4];
  for (int k = 0; k < 4; ++k) f[k] = patch[1 + k / 2][1 + k % 2];
  // x0 and y0 captured by name: clang before 16 cannot capture structured bindings.
  auto centre_of = [&, x0 = x0, y0 = y0](int k) {
    return vec2{(x0 + k % 2 + 0.5) * cell, (y0 + k / 2 + 0.5) * cell};
  };
  // The corners on this side of every wall: the one whose cell holds `p` (or, where that cell
  // is blocked, as walkers at a wall often stand, the nearest finite corner in sight) and those
  // joined to it by an open grid edge.
  int base = (ty < 0.5 ? 0 : 2) + (tx < 0.5 ? 0 : 1);
  if (!std::isfinite(f[base])) {
    base = -1;
    double nearest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
      const double d = (centre_of(k) - p).norm();
      if (std::isfinite(f[k]) && d < nearest && line_clear(p, centre_of(k))) {
        nearest = d;
        base = k;
      }
    }
  }
  // The gradient at each usable corner by central differences (one-sided beside blocked
  // floor), interpolated bilinearly: continuous between cells. Differentiating the bilinear
  // interpolant instead flips the cross component on every cell centre line, so a walker on a
  // valley's floor (the line into a doorway) was sent at one jamb, then the other, and a slow
  // one stood there for good.
  vec2 gradient = vec2::Zero();
  if (base >= 0) {
    const int base_cell = (y0 + base / 2) * grid_w_ + x0 + base % 2;
    double weight_sum = 0.0;
    const unsigned base_edges = edge_blocked_[base_cell];
    for (int k = 0; k < 4; ++k) {
      // One test, rarely true, instead of `k != base` first, which goes either way at random.
      if (!std::isfinite(f[k]) || (base_edges & edge_towards[base][k])) continue;
      const int cx = x0 + k % 2;
      const int cy = y0 + k / 2;
      const auto open = edge_blocked_[cy * grid_w_ + cx];
      auto slope = [&](int dx, int dy) {
        const int i = 1 + k % 2;
        const int j = 1 + k / 2;
        const double ahead =
            (open & (1u << direction_of(dx, dy))) ? unreachable : patch[j + dy][i + dx];
        const double behind =
            (open & (1u << direction_of(-dx, -dy))) ? unreachable : patch[j - dy][i - dx];
        if (std::isfinite(ahead) && std::isfinite(behind)) return (ahead - behind) / (2.0 * cell);
        if (std::isfinite(ahead)) return (ahead - f[k]) / cell;
        if (std::isfinite(behind)) return (f[k] - behind) / cell;
        return 0.0;
      };
      const double weight = (k % 2 ? tx : 1.0 - tx) * (k / 2 ? ty : 1.0 - ty);
      gradient += weight * vec2{slope(1, 0), slope(0, 1)};
      weight_sum += weight;
    }
    if (weight_sum > 1e-6) gradient /= weight_sum;
  }
  const double norm = gradient.norm();
  if (norm > 0.3) return -gradient / norm;
  // At saddles and where no corner is in sight: the slope-weighted mean direction to the
  // visible cells nearby that lie lower than the field here. Every such cell contributes, so
  // equally good neighbours (the three ahead in a corridor) balance instead of the first in
  // scan order winning and pointing the walk into a wall.
  const int c = cell_index(p);
  const int cx = c % grid_w_;
  const int cy = c / grid_w_;
  for (int r = 1; r <= 3; ++r) {
    // The field here: the best visible cell plus the straight walk to it.
    double here = std::numeric_limits<double>::infinity();
    for (int y = cy - r; y <= cy + r; ++y) {
      for (int x = cx - r; x <= cx + r; ++x) {
        const double v = field_at(field, x, y);
        if (!std::isfinite(v)) continue;
        const vec2 centre{(x + 0.5) * cell, (y + 0.5) * cell};
        const double d = (centre - p).norm();
        if (v + d < here && line_clear(p, centre)) here = v + d;
      }
    }
    if (!std::isfinite(here)) continue;
    vec2 sum = vec2::Zero();
    for (int y = cy - r; y <= cy + r; ++y) {
      for (int x = cx - r; x <= cx + r; ++x) {
        const double v = field_at(field, x, y);
        if (!std::isfinite(v) || v >= here) continue;
        const vec2 centre{(x + 0.5) * cell, (y + 0.5) * cell};
        const vec2 to = centre - p;
        const double d = to.norm();
        if (d < 1e-9 || !line_clear(p, centre)) continue;
        const double slope = (here - v) / d;
        sum += to / d * (slope * slope * slope * slope);
      }
    }
    if (sum.norm() > 1e-12) return sum.normalized();
  }
  return vec2::Zero();
}

}  // namespace argus::world
