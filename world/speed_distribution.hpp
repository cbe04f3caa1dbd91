#pragma once

#include <algorithm>
#include <cmath>

#include "world/rng.hpp"

namespace argus::world {

/// The distribution pedestrians' preferred (free) walking speeds are drawn from: a normal
/// distribution truncated to [min_mps, max_mps]. The defaults are Weidmann's (1993) free
/// speed, 1.34 m/s with standard deviation 0.26 m/s, the figure RiMEA test 7 and most
/// pedestrian simulators start from; the bounds cut the tails that no adult walks at.
struct speed_distribution {
  double mean_mps = 1.34;
  double sd_mps = 0.26;
  double min_mps = 0.6;
  double max_mps = 2.0;

  /// One speed, drawn from `random` (Box-Muller; a draw outside the bounds is drawn again, up
  /// to 16 times, then clamped, so a degenerate range still gives a value).
  double draw(rng& random) const noexcept {
    double speed = mean_mps;
    for (int attempt = 0; attempt < 16; ++attempt) {
      const double u1 = 1.0 - random.uniform();  // (0, 1]: log stays finite
      const double u2 = random.uniform();
      speed = mean_mps + sd_mps * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
      if (speed >= min_mps && speed <= max_mps) return speed;
    }
    return std::clamp(speed, min_mps, max_mps);
  }
};

}  // namespace argus::world
