#pragma once

#include <Eigen/Core>
#include <chrono>
#include <optional>

#include "config/scenario.hpp"

namespace argus::vision {

// Angle conventions (those the shipped scenarios assume):
//
//   world: x east, y north, z up, metres; the floor is z = 0.
//   pan:   degrees counter-clockwise from +x on the floor plan (0 = east, 90 = north).
//   tilt:  degrees above the horizon (negative = looking down, -90 = straight down).
//   field of view: the horizontal opening angle, in degrees; zooming in narrows it. Pixels
//          are square, so the vertical opening follows from the aspect ratio.
//   pixels: OpenCV's convention, column u to the right, row v down, (0, 0) the centre of
//          the top-left pixel.
//
//          up  (camera +y)
//           ^
//           |   forward = (cos tilt cos pan, cos tilt sin pan, sin tilt)
//           +----> right = (sin pan, -cos pan, 0)

/// What a camera node may know about itself: its current pan, tilt and field of view (zoom).
/// No position: a camera knows nothing of where it stands (no calibration reaches the node).
/// The one pose type: what the controllers (fixate and zoom, the tracking FSM) command, what
/// relevance (eq. 1) scores, and what the renderer shows.
struct ptz_state {
  double pan_deg = 0.0;
  double tilt_deg = -20.0;
  double field_of_view_deg = 45.0;
  friend bool operator==(const ptz_state&, const ptz_state&) = default;
};

/// The mechanical range and speed of a PTZ head, also known to the node. A static camera has
/// zero-width ranges around its pose and zero rates.
struct ptz_limits {
  config::degree_range pan{-180.0, 180.0};
  config::degree_range tilt{-80.0, 10.0};
  config::degree_range field_of_view{5.0, 90.0};
  double pan_rate_deg_per_s = 60.0;
  double tilt_rate_deg_per_s = 30.0;
  double zoom_rate_deg_per_s = 20.0;

  /// Whether pan turns all the way round (a range of 360 degrees or more): then pan wraps and
  /// slewing takes the shorter way.
  bool pan_wraps() const noexcept { return pan.max_deg - pan.min_deg >= 360.0; }
  /// `wanted` moved into the ranges (pan normalised to (-180, 180] when it wraps).
  ptz_state clamp(const ptz_state& wanted) const noexcept;
  /// The limits a scenario's camera declares; a static camera's collapse onto its pose.
  static ptz_limits from(const config::camera_settings& camera);
};

/// The one motion model of a PTZ head, shared by ptz_camera::step and the controllers: moves
/// `current` toward `goal` (clamped to `limits`) by at most each axis's rate times `dt`,
///   x' = x + clamp(goal - x, -rate dt, rate dt),
/// pan the shorter way round when it wraps (and the result wrapped into (-180, 180]),
/// arriving exactly on the goal once within reach. The result lies within `limits`, so a
/// static camera (collapsed ranges, zero rates) never moves from its pose.
ptz_state slew_towards(const ptz_state& current, const ptz_state& goal, const ptz_limits& limits,
                       config::seconds dt);

/// Where a camera is mounted: known only to the simulator (renderer, emulated sensing), never
/// handed to a camera node.
struct camera_placement {
  /// Optical centre in world metres (plan position, mounting height).
  Eigen::Vector3d position_m{0.0, 0.0, 4.0};
  /// The placement a scenario's camera declares.
  static camera_placement from(const config::camera_settings& camera);
};

/// Everything needed to form one image: mounting, pose and image size. The simulator builds
/// it from the camera node's pose and its own knowledge of the placement.
struct camera_view {
  camera_placement placement;
  ptz_state pose;
  int width_px = 640;
  int height_px = 480;

  /// Focal length in pixels: (width / 2) / tan(fov / 2).
  double focal_px() const noexcept;
  /// Unit vectors of the camera frame in world coordinates (columns: right, up, forward).
  Eigen::Matrix3d orientation() const noexcept;
  /// The pixel (u, v) where world point `p` appears, or nullopt if it lies behind the camera
  /// (not checked against the image bounds, so callers can tell "just outside" apart).
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& p) const;
  /// Unit ray direction in world coordinates through pixel (u, v); the ray starts at the
  /// placement's position.
  Eigen::Vector3d back_project(const Eigen::Vector2d& pixel) const;
  /// Where the ray through pixel (u, v) meets the floor (z = 0), or nullopt above the horizon.
  std::optional<Eigen::Vector3d> floor_point(const Eigen::Vector2d& pixel) const;
  /// OpenGL view matrix (world -> eye, eye looking down -z).
  Eigen::Matrix4f gl_view() const noexcept;
  /// OpenGL projection matrix matching focal_px(); `flip_y` renders rows top-down so that a
  /// glReadPixels result is already in OpenCV row order.
  Eigen::Matrix4f gl_projection(double near_m, double far_m, bool flip_y) const noexcept;
};

/// A camera_view's projection with the pose's trigonometry done once: what to use when many
/// points are projected through one pose. Gives exactly camera_view::project's pixels.
class camera_projection {
 public:
  explicit camera_projection(const camera_view& view);

  /// camera_view::focal_px().
  double focal_px() const noexcept { return focal_px_; }
  /// The optical axis in world coordinates (camera_view::orientation()'s third column).
  Eigen::Vector3d forward() const { return orientation_.col(2); }
  /// camera_view::project(p).
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& p) const;

 private:
  Eigen::Matrix3d orientation_;
  Eigen::Vector3d position_m_;
  double focal_px_;
  double width_px_;
  double height_px_;
};

/// A PTZ head: holds the pose and moves it toward a commanded pose at the configured slew
/// rates, one time step at a time. The camera node owns one; the simulator reads its pose.
class ptz_camera {
 public:
  /// A head with `limits` starting at `initial` (clamped).
  ptz_camera(ptz_limits limits, ptz_state initial);
  /// The head of a scenario camera, at its default pose.
  static ptz_camera from(const config::camera_settings& camera);

  /// The current pose.
  const ptz_state& state() const noexcept { return state_; }
  /// The pose being slewed to.
  const ptz_state& target() const noexcept { return target_; }
  /// The limits.
  const ptz_limits& limits() const noexcept { return limits_; }

  /// Sets the pose to slew to (clamped to the limits); movement happens in step().
  void command(const ptz_state& wanted);
  /// Moves each axis toward the target by at most its rate times `dt`: slew_towards().
  void step(config::seconds dt);
  /// Whether the pose has reached the target.
  bool settled() const noexcept { return state_ == target_; }

 private:
  ptz_limits limits_;
  ptz_state state_;
  ptz_state target_;
};

}  // namespace argus::vision
