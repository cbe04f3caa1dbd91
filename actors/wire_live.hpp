#pragma once

// A live run (`argus serve --workers`) across processes (docs/distributed.md, "Live runs"): the
// operator's orders go out to the workers with the world's snapshot, and what the console shows
// of their cameras (pose, frame, the tracker's boxes, traffic) comes back with each gather.
// Display only on the way back: nothing of it feeds the run.

#include <cstdint>
#include <optional>
#include <vector>

#include "actors/operator_board.hpp"
#include "actors/wire_double.hpp"
#include "actors/wire_log.hpp"
#include "config/scenario.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::config {

// The scenario's own types, crossing as their parts: times as the bits of their seconds, the
// target choice as its number, the cancellation as a flag and a time.
template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, operator_task& x) {
  using actors::as_bits;
  double at_s = x.at.count();
  auto by = static_cast<std::uint8_t>(x.by);
  bool cancels = x.cancel_at.has_value();
  double cancel_s = cancels ? x.cancel_at->count() : 0.0;
  auto fields = [&] {
    return f(as_bits(at_s), x.pedestrian, x.camera, x.cameras_wanted, x.max_cameras, by,
             as_bits(x.pixel.x_px), as_bits(x.pixel.y_px), cancels, as_bits(cancel_s));
  };
  if constexpr (Inspector::reads_state) {
    return fields();
  } else {
    auto result = fields();
    x.at = seconds{at_s};
    x.by = static_cast<task_target>(by);
    x.cancel_at = cancels ? std::optional<seconds>{seconds{cancel_s}} : std::nullopt;
    return result;
  }
}

}  // namespace argus::config

namespace argus::actors {

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, operator_order& x) {
  return f(x.tick, x.camera, x.task, x.cancel, x.request);
}

/// What the console shows of one camera on a worker after its turn: its pose, and the frame it
/// sensed (as JPEG; empty when it looked at nothing) with the tracker's boxes in it.
struct camera_display {
  int camera = 0;
  /// The tick of the frame (of the turn, when there is none).
  std::int64_t tick = 0;
  vision::ptz_state pose;
  std::vector<std::uint8_t> jpeg;
  /// x, y, width, height of each box, one after the other.
  std::vector<double> boxes;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, camera_display& x) {
  return f(x.camera, x.tick, x.pose, x.jpeg, x.boxes);
}

/// The cameras whose frames the console wants (`live::console_state::watched`): a worker encodes
/// and sends only these cameras' frames with its gathers.
struct display_watch {
  std::vector<int> cameras;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, display_watch& x) {
  return f(x.cameras);
}

/// A worker's cameras as the console shows them, since it was last asked: each camera's latest
/// turn, and the network messages they sent and received.
struct live_display {
  std::vector<camera_display> cameras;
  std::uint64_t sent = 0;
  std::uint64_t received = 0;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, live_display& x) {
  return f(x.cameras, x.sent, x.received);
}

}  // namespace argus::actors
