#include "protocol/csp_table1.hpp"

#include <numeric>
#include <stdexcept>
#include <utility>

#include "pcg_random.hpp"

namespace argus::protocol {
namespace {

/// Uniform in [0, bound), without modulo bias.
std::uint64_t draw_below(pcg64& rng, std::uint64_t bound) {
  const std::uint64_t limit = pcg64::max() - pcg64::max() % bound;
  std::uint64_t x;
  do x = rng();
  while (x >= limit);
  return x % bound;
}

/// Uniform in [0, 1) with 53 random bits.
double draw_unit(pcg64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

}  // namespace

csp_problem make_table1_instance(const table1_setting& setting, std::uint64_t seed) {
  if (setting.shared > setting.relevant_per_group)
    throw std::invalid_argument("table1: more shared cameras than relevant ones");
  const std::size_t pool = 2 * setting.relevant_per_group - setting.shared;
  pcg64 rng(seed);
  std::vector<std::size_t> order(pool);
  std::iota(order.begin(), order.end(), std::size_t{0});
  for (std::size_t i = pool; i > 1; --i) std::swap(order[i - 1], order[draw_below(rng, i)]);

  csp_problem problem;
  problem.camera_count = pool;
  problem.threshold = setting.threshold;
  const std::size_t first[2] = {0, pool - setting.relevant_per_group};
  for (std::size_t g = 0; g < 2; ++g) {
    csp_group group;
    group.min_cameras = setting.cameras_per_group;
    group.max_cameras = setting.cameras_per_group;
    group.relevance.assign(pool, 0.0);
    std::vector<bool> relevant(pool, false);
    for (std::size_t i = 0; i < setting.relevant_per_group; ++i)
      relevant[order[first[g] + i]] = true;
    for (std::size_t c = 0; c < pool; ++c)
      if (relevant[c])
        group.relevance[c] = setting.threshold + (1.0 - setting.threshold) * draw_unit(rng);
    problem.groups.push_back(std::move(group));
  }
  return problem;
}

}  // namespace argus::protocol
