#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "world/pedestrian.hpp"

namespace argus::world {

/// The neighbour index's people as columns, in its cell order (snapshot::columns).
struct neighbour_columns {
  const double* x = nullptr;
  const double* y = nullptr;
  const double* vx = nullptr;
  const double* vy = nullptr;
  const double* radius = nullptr;
};

/// Who among the people around a walker can change its step (step_pedestrian's neighbour
/// visit): someone near (the repulsion, the constraints, the arch test), or someone farther
/// in the lane ahead within the look-ahead (the way's free path) or coming the other way (the
/// side step), or, for a walker who may turn, in a turned heading's lane. Everyone else would
/// only lose a comparison in the visit, so leaving them out changes no result. The tests
/// repeat the visit's own arithmetic; the margins only widen them. The distance floor leaves
/// out the walker itself.
///
/// `matters` weighs one person; `sift` weighs a run of the index's columns two at a time,
/// without a branch (which ones matter is a coin toss to the branch predictor, and the
/// columns spare reading a whole record for the half that are out of reach). They agree
/// person for person.
struct neighbour_sieve {
  vec2 position{0.0, 0.0};
  /// The way the walker wants to go: a unit vector, or zero.
  vec2 direction{0.0, 0.0};
  double radius = 0.0;
  /// Beyond body contact plus this, no force or constraint reaches.
  double near_gap_m = 0.0;
  double reach_squared = 0.0;
  /// The look-ahead, with its margin.
  double look_m = 0.0;
  /// Side-step margin across one's path, with its margin.
  double lane_margin_m = 0.0;
  bool turning = false;

  static constexpr double sqrt_two = 1.4142135623730951 + 1e-9;

  bool matters(double x, double y, double vx, double vy, double other_radius) const {
    const double ox = x - position.x();
    const double oy = y - position.y();
    const double distance_squared = ox * ox + oy * oy;
    const double contact = radius + other_radius;
    const double near_m = contact + near_gap_m;
    const double along = ox * direction.x() + oy * direction.y();
    const double across = std::abs(ox * direction.y() - oy * direction.x());
    const bool in_reach = !(distance_squared > reach_squared) & !(distance_squared < 1e-18);
    const bool near = distance_squared < near_m * near_m;
    const bool in_lane = (along > 0.0) & (across < contact + lane_margin_m);
    const bool slows = along - contact < look_m;
    const bool oncoming = vx * direction.x() + vy * direction.y() < -0.1 + 1e-9;
    // In a turned heading's lane (within 45 degrees of the way, widened by contact across the
    // outermost heading) and near enough to shorten its free path below the look-ahead (a
    // free path is at least the distance less two contacts).
    const double view_m = look_m + 2.0 * contact;
    const bool in_cone =
        turning & (along > across - sqrt_two * contact) & (distance_squared < view_m * view_m);
    return in_reach & (near | in_cone | (in_lane & (slows | oncoming)));
  }

  /// Writes the indices in [begin, end) of those who matter to `picked`, in order; returns
  /// how many.
  std::size_t sift(const neighbour_columns& c, std::uint32_t begin, std::uint32_t end,
                   std::uint32_t* picked) const {
#if defined(__SSE2__)
    const lanes l(*this);
    std::size_t count = 0;
    std::uint32_t k = begin;
    for (; k + 2 <= end; k += 2) {
      const int kept =
          l.matters(_mm_loadu_pd(c.x + k), _mm_loadu_pd(c.y + k), _mm_loadu_pd(c.vx + k),
                    _mm_loadu_pd(c.vy + k), _mm_loadu_pd(c.radius + k));
      picked[count] = k;
      count += static_cast<std::size_t>(kept & 1);
      picked[count] = k + 1;
      count += static_cast<std::size_t>(kept >> 1);
    }
    return count + sift_one_by_one(c, k, end, picked + count);
#else
    return sift_one_by_one(c, begin, end, picked);
#endif
  }

  /// sift weighing one person at a time (the reference sift must agree with).
  std::size_t sift_one_by_one(const neighbour_columns& c, std::uint32_t begin, std::uint32_t end,
                              std::uint32_t* picked) const {
    std::size_t count = 0;
    for (std::uint32_t k = begin; k < end; ++k) {
      picked[count] = k;
      count += static_cast<std::size_t>(matters(c.x[k], c.y[k], c.vx[k], c.vy[k], c.radius[k]));
    }
    return count;
  }

 private:
#if defined(__SSE2__)
  /// `matters` for two people at once, term for term; returns a bit for each.
  struct lanes {
    explicit lanes(const neighbour_sieve& s)
        : px(_mm_set1_pd(s.position.x())),
          py(_mm_set1_pd(s.position.y())),
          dx(_mm_set1_pd(s.direction.x())),
          dy(_mm_set1_pd(s.direction.y())),
          radius(_mm_set1_pd(s.radius)),
          near_gap(_mm_set1_pd(s.near_gap_m)),
          reach_squared(_mm_set1_pd(s.reach_squared)),
          look(_mm_set1_pd(s.look_m)),
          lane_margin(_mm_set1_pd(s.lane_margin_m)),
          turning(_mm_castsi128_pd(_mm_set1_epi64x(s.turning ? -1 : 0))) {}

    int matters(__m128d x, __m128d y, __m128d vx, __m128d vy, __m128d other_radius) const {
      const __m128d zero = _mm_setzero_pd();
      const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
      const __m128d ox = _mm_sub_pd(x, px);
      const __m128d oy = _mm_sub_pd(y, py);
      const __m128d distance_squared = _mm_add_pd(_mm_mul_pd(ox, ox), _mm_mul_pd(oy, oy));
      const __m128d contact = _mm_add_pd(radius, other_radius);
      const __m128d near_m = _mm_add_pd(contact, near_gap);
      const __m128d along = _mm_add_pd(_mm_mul_pd(ox, dx), _mm_mul_pd(oy, dy));
      const __m128d across =
          _mm_and_pd(_mm_sub_pd(_mm_mul_pd(ox, dy), _mm_mul_pd(oy, dx)), magnitude);
      // !(a > b) and !(a < b) as the scalar code has them: false-on-NaN comparisons negated.
      const __m128d in_reach = _mm_and_pd(_mm_cmpngt_pd(distance_squared, reach_squared),
                                          _mm_cmpnlt_pd(distance_squared, _mm_set1_pd(1e-18)));
      const __m128d near = _mm_cmplt_pd(distance_squared, _mm_mul_pd(near_m, near_m));
      const __m128d in_lane = _mm_and_pd(_mm_cmpgt_pd(along, zero),
                                         _mm_cmplt_pd(across, _mm_add_pd(contact, lane_margin)));
      const __m128d slows = _mm_cmplt_pd(_mm_sub_pd(along, contact), look);
      const __m128d oncoming = _mm_cmplt_pd(_mm_add_pd(_mm_mul_pd(vx, dx), _mm_mul_pd(vy, dy)),
                                            _mm_set1_pd(-0.1 + 1e-9));
      const __m128d view_m = _mm_add_pd(look, _mm_mul_pd(_mm_set1_pd(2.0), contact));
      const __m128d in_cone = _mm_and_pd(
          turning,
          _mm_and_pd(
              _mm_cmpgt_pd(along, _mm_sub_pd(across, _mm_mul_pd(_mm_set1_pd(sqrt_two), contact))),
              _mm_cmplt_pd(distance_squared, _mm_mul_pd(view_m, view_m))));
      const __m128d kept = _mm_and_pd(
          in_reach,
          _mm_or_pd(_mm_or_pd(near, in_cone), _mm_and_pd(in_lane, _mm_or_pd(slows, oncoming))));
      return _mm_movemask_pd(kept);
    }

    __m128d px, py, dx, dy, radius, near_gap, reach_squared, look, lane_margin, turning;
  };
#endif
};

}  // namespace argus::world
