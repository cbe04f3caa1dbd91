#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <vector>

#include "controller/controller_io.hpp"
#include "vision/emulated_sensor.hpp"

namespace argus::sensing {

/// A camera node's sensing through the emulated sensor (vision::emulated_sensor), for runs
/// too large to render: what the pixel tracker would report, from ground truth through the
/// calibrated error model. Simulator-side: it sees the snapshot, but hands the node only
/// boxes in its frame.
///
/// A target is known to the node only by its signature, so this finds it the way colour
/// indexing would: the visible pedestrian whose appearance best matches the signature
/// (normalised intersection at least `min_match`), keeping to the one it followed last while
/// that one still matches (a tracker follows what it has, right or wrong); then the error
/// model decides miss or confusion (emulated_sensor::look_for).
class emulated_looks {
 public:
  emulated_looks(vision::sensor_model model, std::uint64_t run_seed, int camera_id,
                 double min_match = 0.4);

  /// Whether pedestrian `id` is task `task`'s (sensing.identity: ground_truth).
  using truth_check = std::function<bool(controller::task_id task, int id)>;

  /// Looks for every requested target in `frame` as seen through `view`. With `is_target`, of the
  /// pedestrians matching the signature only the task's own is taken (a perfect
  /// re-identification); the error model still decides whether she is missed.
  std::vector<controller::look_result> look(const world::snapshot& frame,
                                            const world::station& where,
                                            const vision::camera_view& view,
                                            const std::vector<controller::look_request>& looks,
                                            const truth_check& is_target = {});

  /// The operator picked pedestrian `id` for `task`: the signature of its appearance.
  protocol::signature acquire(controller::task_id task, const world::snapshot& frame, int id);

 private:
  const vision::color_histogram& signature_of(const world::appearance& look);

  vision::emulated_sensor sensor_;
  double min_match_;
  // Signatures by appearance, made once: palettes are small. A deque, since references to
  // its elements must survive later insertions.
  std::deque<std::pair<world::appearance, vision::color_histogram>> signatures_;
  std::map<controller::task_id, int> following_;
};

}  // namespace argus::sensing
