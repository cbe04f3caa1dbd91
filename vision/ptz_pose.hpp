#pragma once

// The pan, tilt and field of view of a PTZ camera: all that the image-driven controllers and
// the relevance metric know about a camera (no calibration, no world positions).
//
// Conventions: pan turns about the vertical axis and increases to the left (counter-clockwise
// seen from above); tilt increases upwards (negative looks down); the field of view is the
// horizontal one, spanning the frame width (pinhole: f_px = (w / 2) / tan(fov / 2)), square
// pixels. These match vision/ptz_camera.hpp (the renderer's camera model). Image x
// grows to the right and y downwards.

namespace argus::vision {

/// Pan, tilt and horizontal field of view, in degrees.
struct ptz_pose {
  double pan_deg = 0.0;
  double tilt_deg = 0.0;
  double field_of_view_deg = 45.0;
  friend bool operator==(const ptz_pose&, const ptz_pose&) = default;
};

/// A frame's size in pixels.
struct frame_size {
  int width_px = 640;
  int height_px = 480;
};

}  // namespace argus::vision
