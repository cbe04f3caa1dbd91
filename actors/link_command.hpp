#pragma once

#include <cstdint>

#include "actors/wire_double.hpp"
#include "caf/actor.hpp"

namespace argus::actors {

/// What the fault injector (or the assembly) tells a link.
enum class link_op : std::uint8_t {
  attach = 0,       ///< `node`'s actor is now `handle` (start, or back after a crash)
  node_down = 1,    ///< `node` crashed: messages reaching it are dropped
  cut = 2,          ///< the link is cut: everything on it is lost until healed
  heal = 3,         ///< the cut is healed
  loss_burst = 4,   ///< loss probability is `loss_probability` until tick `until_tick`
  delay_spike = 5,  ///< every message sent until tick `until_tick` takes `extra_ticks` longer
};

/// One command to a link.
struct link_command {
  link_op op = link_op::attach;
  int node = 0;
  caf::actor handle;
  double loss_probability = 0.0;
  std::int64_t until_tick = 0;
  std::int64_t extra_ticks = 0;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, link_command& x) {
  return f(x.op, x.node, x.handle, as_bits(x.loss_probability), x.until_tick, x.extra_ticks);
}

}  // namespace argus::actors
