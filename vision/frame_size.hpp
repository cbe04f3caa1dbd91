#pragma once

namespace argus::vision {

/// A frame's size in pixels (image x grows to the right and y downwards; see ptz_camera.hpp
/// for the angle conventions).
struct frame_size {
  int width_px = 640;
  int height_px = 480;
};

}  // namespace argus::vision
