#pragma once

// The observation log's records as they cross between a worker and the coordinator
// (docs/distributed.md): CAF inspectors, so the middleman serialises them; doubles as their bits
// (wire_double.hpp).

#include <cstdint>

#include "actors/wire_double.hpp"
#include "actors/wire_frames.hpp"
#include "eval/observation_log.hpp"
#include "eval/records.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::vision {

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, ptz_state& x) {
  return f(actors::as_bits(x.pan_deg), actors::as_bits(x.tilt_deg),
           actors::as_bits(x.field_of_view_deg));
}

}  // namespace argus::vision

namespace argus::eval {

// cv::Rect2d is OpenCV's, out of reach of argument-dependent lookup: its members go one by one.
template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, look_record& x) {
  using actors::as_bits;
  return f(x.task, x.leader, x.found, as_bits(x.box.x), as_bits(x.box.y), as_bits(x.box.width),
           as_bits(x.box.height), as_bits(x.score), x.truth, as_bits(x.iou), x.observed);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, visible_box& x) {
  using actors::as_bits;
  return f(x.pedestrian, as_bits(x.box.x), as_bits(x.box.y), as_bits(x.box.width),
           as_bits(x.box.height), as_bits(x.visibility));
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, camera_frame& x) {
  return f(x.tick, x.camera, x.pose, x.state, x.looks, x.visible);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, task_origin& x) {
  return f(x.task, x.pedestrian, x.camera, x.tick, x.by);
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, target_sample& x) {
  using actors::as_bits;
  return f(x.tick, x.task, x.pedestrian, as_bits(x.x_m), as_bits(x.y_m), as_bits(x.height_m),
           x.present);
}

/// A worker sends its whole log when the run is over (actors/worker_host.hpp).
template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, observation_log::contents& x) {
  return f(actors::as_frames(x.frames), x.origins, x.cancels, x.samples, x.sent, x.sent_by_tick,
           x.sent_after_cancel);
}

}  // namespace argus::eval
