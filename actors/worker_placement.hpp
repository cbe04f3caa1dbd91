#pragma once

#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "config/scenario.hpp"

namespace argus::actors {

/// Which worker (0 .. workers - 1) hosts each camera, by camera id: every worker gets
/// `cameras / workers` cameras or one more, the first workers the extra ones. Throws
/// std::invalid_argument when there are more workers than cameras.
/// `scenario.placement.policy` says how (docs/distributed.md, "Placement").
std::map<int, std::size_t> place_cameras(const config::scenario& scenario, std::size_t workers);

/// Which worker hosts the link between cameras `a` and `b`: camera `a`'s.
inline std::size_t place_link(const std::map<int, std::size_t>& cameras, int a, int /*b*/) {
  return cameras.at(a);
}

}  // namespace argus::actors
