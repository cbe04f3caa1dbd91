#pragma once

#include "config/scenario.hpp"

namespace argus::vision::test_support {

/// A scenario's static camera fixed at pan 30, tilt -25 and the field of view `fov_deg`: its
/// ptz_limits collapse onto that pose.
inline config::camera_settings static_camera(double fov_deg = 40.0) {
  config::camera_settings camera;
  camera.type = config::camera_type::static_camera;
  camera.pan_deg = 30.0;
  camera.tilt_deg = -25.0;
  camera.field_of_view_deg = fov_deg;
  return camera;
}

}  // namespace argus::vision::test_support
