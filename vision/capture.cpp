#include "vision/capture.hpp"

#include "vision/renderer.hpp"
#include "world/snapshot.hpp"

namespace argus::vision {

cv::Mat capture(renderer& renderer, const camera_view& view, const world::snapshot& frame,
                double time_s, double field_interval_s, imaging_model& model) {
  if (!model.interlaced()) return model.degrade(renderer.render(view, frame, time_s));
  return model.degrade(renderer.render_interlaced(view, frame, time_s, time_s + field_interval_s));
}

}  // namespace argus::vision
