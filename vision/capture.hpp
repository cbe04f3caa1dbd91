#pragma once

#include <opencv2/core/mat.hpp>

#include "vision/imaging_model.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::world {
class snapshot;
}  // namespace argus::world

namespace argus::vision {

class renderer;

/// What a camera delivers for the frame at `time_s` (Section III-A): its view of `frame`
/// rendered, in two fields `field_interval_s` apart when `model` interlaces
/// (renderer::render_interlaced), then degraded by `model`, whose noise moves on. Every path
/// that shows a camera's degraded view goes through here: a run's sensing and video, feeds,
/// `argus render`, `argus feeds`, the benches.
cv::Mat capture(renderer& renderer, const camera_view& view, const world::snapshot& frame,
                double time_s, double field_interval_s, imaging_model& model);

}  // namespace argus::vision
