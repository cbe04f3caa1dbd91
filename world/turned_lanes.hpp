#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "world/pedestrian.hpp"

namespace argus::world {

/// The free path along unit `direction` before touching someone at `offset` with body contact
/// `contact`, or `shortest` when that is shorter: infinite unless their centre lies ahead and
/// within `lane_fraction` of contact across the path (step_pedestrian's headway).
inline double free_path_to(const vec2& offset, double contact, const vec2& direction,
                           double lane_fraction, double shortest) {
  const double ahead = offset.x() * direction.x() + offset.y() * direction.y();
  const double aside = std::abs(offset.x() * direction.y() - offset.y() * direction.x());
  if (!(ahead > 0.0) || !(aside < lane_fraction * contact)) return shortest;
  return std::min(shortest, std::max(ahead - std::sqrt(contact * contact - aside * aside), 0.0));
}

/// The people who may stand in a walker's turned headings (step_pedestrian's heading choice),
/// kept during the neighbour visit and weighed after it, heading by heading.
///
/// Those near enough to block a turn (a free path under `block_m` needs a centre within
/// sqrt((block_m + contact)^2 + contact^2)) are kept apart from the others and weighed first,
/// so a blocked heading is known after a few. Past the capacity the last visited are left
/// out, the same ones every run. Columns, not records, weighed two at a time without a branch:
/// a jammed walker weighs six headings, and one person after another, each waiting on the
/// last one's square root and exit test, was a fifth of a packed station's step.
class turned_lanes {
 public:
  static constexpr std::size_t capacity = 96;

  explicit turned_lanes(double block_m) : block_m_(block_m) {}

  /// Keeps someone at `offset` from the walker with body contact `contact`; `distance_squared`
  /// is offset.squaredNorm().
  void keep(const vec2& offset, double contact, double distance_squared) {
    if (blockers_ + others_ == capacity) return;
    const double reach_m = block_m_ + contact;
    // The bound's margin only moves a few people into the first group; the result is the same.
    const std::size_t at = distance_squared < reach_m * reach_m + contact * contact + 1e-9
                               ? blockers_++
                               : capacity - ++others_;
    x_[at] = offset.x();
    y_[at] = offset.y();
    contact_[at] = contact;
  }

  /// The free path along unit `direction`, at most `path`, before touching someone kept whose
  /// centre lies ahead and within `lane_fraction` of body contact across it. The same
  /// arithmetic as the way's own free path. Under `block_m` the value is only an upper bound:
  /// the heading is out, and the rest are not weighed.
  double free_path(const vec2& direction, double lane_fraction, double path) const {
#if defined(__SSE2__)
    return blockers_then_others(&turned_lanes::least_in_pairs, direction, lane_fraction, path);
#else
    return free_path_one_by_one(direction, lane_fraction, path);
#endif
  }

  /// free_path weighing one person at a time (the reference free_path must agree with).
  double free_path_one_by_one(const vec2& direction, double lane_fraction, double path) const {
    return blockers_then_others(&turned_lanes::least_one_by_one, direction, lane_fraction, path);
  }

 private:
  using least_of = double (turned_lanes::*)(std::size_t, std::size_t, const vec2&, double, double,
                                            bool) const;

  double blockers_then_others(least_of least, const vec2& direction, double lane_fraction,
                              double path) const {
    path = (this->*least)(0, blockers_, direction, lane_fraction, path, true);
    if (path < block_m_) return path;
    return (this->*least)(capacity - others_, capacity, direction, lane_fraction, path, false);
  }

  double least_one_by_one(std::size_t begin, std::size_t end, const vec2& direction,
                          double lane_fraction, double path, bool stop_when_blocked) const {
    for (std::size_t j = begin; j < end; ++j) {
      path = free_path_to({x_[j], y_[j]}, contact_[j], direction, lane_fraction, path);
      if (stop_when_blocked && path < block_m_) return path;
    }
    return path;
  }

#if defined(__SSE2__)
  // Two people a lane: SSE2 is in every x86-64, and the compiler, left to itself, branched on
  // every test. The arithmetic is free_path_to's, term for term; a root is taken for
  // everyone (of zero outside the lane) and the lane test picks what counts.
  double least_in_pairs(std::size_t begin, std::size_t end, const vec2& direction,
                        double lane_fraction, double path, bool stop_when_blocked) const {
    const __m128d dx = _mm_set1_pd(direction.x());
    const __m128d dy = _mm_set1_pd(direction.y());
    const __m128d lane = _mm_set1_pd(lane_fraction);
    const __m128d zero = _mm_setzero_pd();
    const __m128d never = _mm_set1_pd(std::numeric_limits<double>::infinity());
    const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
    __m128d least = _mm_set1_pd(path);
    const auto weigh = [&](__m128d x, __m128d y, __m128d contact) {
      const __m128d ahead = _mm_add_pd(_mm_mul_pd(x, dx), _mm_mul_pd(y, dy));
      const __m128d aside = _mm_and_pd(_mm_sub_pd(_mm_mul_pd(x, dy), _mm_mul_pd(y, dx)), magnitude);
      const __m128d root = _mm_sqrt_pd(
          _mm_max_pd(_mm_sub_pd(_mm_mul_pd(contact, contact), _mm_mul_pd(aside, aside)), zero));
      const __m128d free = _mm_max_pd(_mm_sub_pd(ahead, root), zero);
      const __m128d in_lane =
          _mm_and_pd(_mm_cmpgt_pd(ahead, zero), _mm_cmplt_pd(aside, _mm_mul_pd(lane, contact)));
      least =
          _mm_min_pd(least, _mm_or_pd(_mm_and_pd(in_lane, free), _mm_andnot_pd(in_lane, never)));
    };
    const auto lowest = [&] {
      return std::min(_mm_cvtsd_f64(least), _mm_cvtsd_f64(_mm_unpackhi_pd(least, least)));
    };
    std::size_t j = begin;
    for (; j + 2 <= end; j += 2) {
      weigh(_mm_loadu_pd(&x_[j]), _mm_loadu_pd(&y_[j]), _mm_loadu_pd(&contact_[j]));
      if (stop_when_blocked && (j - begin) % 4 == 2 && lowest() < block_m_) return lowest();
    }
    // An odd one out: the empty lane is a person at the walker's centre, never ahead.
    if (j < end) weigh(_mm_load_sd(&x_[j]), _mm_load_sd(&y_[j]), _mm_load_sd(&contact_[j]));
    return lowest();
  }
#endif

  double block_m_;
  std::size_t blockers_ = 0;
  std::size_t others_ = 0;
  // Blockers fill from the front, the others from the back. Left unfilled, not zeroed.
  std::array<double, capacity> x_;
  std::array<double, capacity> y_;
  std::array<double, capacity> contact_;
};

}  // namespace argus::world
