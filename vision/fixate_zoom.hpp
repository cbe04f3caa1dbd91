#pragma once

// Image-driven fixate and zoom (Section III-B): pan/tilt to bring a box to the image centre,
// field of view so that it fills a set fraction of the frame height. They use only the
// camera's own pan, tilt and field of view and the box in pixels (pinhole relation between
// field of view and focal length; no calibration, no world positions). See ptz_camera.hpp for
// the angle conventions and the motion model (slew_towards) they share with the renderer.

#include "config/scenario.hpp"
#include "opencv2/core.hpp"
#include "vision/frame_size.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::vision {

/// Pinhole focal length in pixels for a horizontal field of view: (w / 2) / tan(fov / 2).
double focal_length_px(double field_of_view_deg, int frame_width_px);

/// A camera's axes at `pose` in the base frame (z up, pan 0 along x).
struct camera_axes {
  cv::Vec3d forward;
  cv::Vec3d right;
  cv::Vec3d up;
};

/// The axes of a pan-tilt head at `pose`: pan about the vertical, tilt about the panned
/// horizontal axis.
camera_axes axes_of(const ptz_state& pose);

/// The ray (base frame, not normalised: its forward part is the focal length) through
/// `pixel` of a frame taken at `pose`.
cv::Vec3d ray_through(const cv::Point2d& pixel, const ptz_state& pose, const frame_size& frame);

/// The pose that centres the box's centre in the image (exactly, for a pan-tilt head: pan
/// about the vertical, tilt about the panned horizontal axis) with a field of view in which
/// the box's height is `height_fraction` of the frame height. Not clamped to any limits: this
/// is the "pan, tilt and zoom required to centre the pedestrian" of eq. (1).
ptz_state centring_pose(const ptz_state& current, const cv::Rect2d& box, const frame_size& frame,
                        double height_fraction = 0.5);

/// Gains and set point of the fixate and zoom controllers.
struct fixate_zoom_settings {
  /// Fraction of the pan/tilt error corrected per step, in (0, 1]; < 1 does not overshoot.
  double fixate_gain = 0.5;
  /// Fraction of the field-of-view error corrected per step, in (0, 1].
  double zoom_gain = 0.3;
  /// Box height as a fraction of the frame height that zoom aims for.
  double height_fraction = 0.5;
  /// Pan/tilt errors below this are left alone (degrees).
  double dead_band_deg = 0.1;
};

/// One step of fixate and zoom: moves `current` a fraction of the way to centring_pose(),
/// within `limits` and their slew rates over `dt` (slew_towards(), the model ptz_camera::step
/// follows: commanding the result and stepping the head by `dt` shows exactly this pose).
ptz_state fixate_zoom_step(const ptz_state& current, const cv::Rect2d& box, const frame_size& frame,
                           const ptz_limits& limits, config::seconds dt,
                           const fixate_zoom_settings& settings = {});

}  // namespace argus::vision
