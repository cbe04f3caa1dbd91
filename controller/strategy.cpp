#include "controller/strategy.hpp"

namespace argus::controller {

node_identity node_identity::from(const config::camera_settings& camera) {
  node_identity me;
  me.id = camera.id;
  me.limits = vision::ptz_limits::from(camera);
  me.home = vision::ptz_state{camera.pan_deg, camera.tilt_deg, camera.field_of_view_deg};
  me.frame = vision::frame_size{static_cast<int>(camera.imaging.width_px),
                                static_cast<int>(camera.imaging.height_px)};
  return me;
}

std::string_view name_of(node_state s) {
  switch (s) {
    case node_state::idle:
      return "idle";
    case node_state::computing_relevance:
      return "computing_relevance";
    case node_state::performing_task:
      return "performing_task";
  }
  return "idle";
}

}  // namespace argus::controller
