#pragma once

#include <Eigen/Core>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <span>
#include <string>
#include <vector>

#include "vision/egl_context.hpp"
#include "vision/pedestrian_mesh.hpp"
#include "vision/ptz_camera.hpp"
#include "world/pedestrian.hpp"

namespace argus::world {
class snapshot;
class station;
}  // namespace argus::world

namespace argus::vision {

/// A bright cube drawn unlit by render_markers: for checking the camera model against the
/// pixels (a marker at a known world point must appear where camera_view::project says).
struct marker {
  Eigen::Vector3d position_m{0.0, 0.0, 0.0};
  double size_m = 0.2;
  world::rgb8 color{255, 255, 255};
};

/// Headless renderer of a camera's view of the station (Section III-A: "the standard graphics
/// pipeline"): the station's static geometry (uploaded once) and every pedestrian of a
/// snapshot as an articulated low-poly figure, with Lambert lighting, drawn into a
/// framebuffer object and read back as an OpenCV BGR image.
///
/// One renderer = one EGL context: use it from one thread at a time (it binds the context
/// at the start of each call and releases it at the end, so successive calls may come from
/// different threads). Renderers are independent; a pool of N renders N views in parallel.
class renderer {
 public:
  /// Creates the context (see egl_context for the platform choice) and uploads the static
  /// geometry of `where` (nullptr: markers only). Throws std::runtime_error naming what
  /// failed (no EGL device, shader compile error, incomplete framebuffer).
  explicit renderer(std::shared_ptr<const world::station> where);
  ~renderer();
  renderer(const renderer&) = delete;
  renderer& operator=(const renderer&) = delete;

  /// The view of `frame`'s pedestrians in the station at virtual time `time_s` (which drives
  /// the gait; pedestrians stand where the snapshot puts them) as a CV_8UC3 BGR image of
  /// view.width_px x view.height_px.
  cv::Mat render(const camera_view& view, const world::snapshot& frame, double time_s);

  /// The same view of pedestrians given directly (tests, tools), without a snapshot.
  cv::Mat render(const camera_view& view, std::span<const world::pedestrian_state> people,
                 double time_s);

  /// An interlaced frame as an interlaced sensor takes it (Section III-A): its even rows
  /// (0, 2, ...) show `frame` at `first_time_s`, its odd rows at `second_time_s`. Each field is
  /// rasterised at its own rows only, both in one pass and one read-back: the rows of two
  /// full renders woven together (weave_fields), up to rounding at the edges of shapes, for
  /// half their pixels.
  cv::Mat render_interlaced(const camera_view& view, const world::snapshot& frame,
                            double first_time_s, double second_time_s);

  /// The same with the fields' pedestrians given directly (tests, tools).
  cv::Mat render_interlaced(const camera_view& view,
                            std::span<const world::pedestrian_state> first_people,
                            double first_time_s,
                            std::span<const world::pedestrian_state> second_people,
                            double second_time_s);

  /// A test scene: unlit marker cubes on a uniform `background`, no station.
  cv::Mat render_markers(const camera_view& view, std::span<const marker> markers,
                         world::rgb8 background = {0, 0, 0});

  /// Which EGL platform, device and GL version render (for logs and benchmark records).
  const std::string& device() const noexcept { return context_.description(); }

  /// Near and far clipping distances, metres.
  static constexpr double near_m = 0.25;
  static constexpr double far_m = 500.0;

 private:
  struct gl_objects;
  /// One rasterisation of the view into rows [first_row, first_row + rows) of the framebuffer.
  struct pass {
    int first_row = 0;
    int rows = 0;
    Eigen::Matrix4f view_projection;
    const std::vector<box_instance>* boxes = nullptr;
  };
  void collect_boxes(const camera_view& view, std::span<const world::pedestrian_state> people,
                     double time_s, std::vector<box_instance>& out) const;
  /// Draws `passes` into a framebuffer of the view's size and reads it back (BGR, top row
  /// first, as the framebuffer's rows are).
  cv::Mat draw(const camera_view& view, bool with_station, std::span<const pass> passes, bool lit,
               world::rgb8 background);

  egl_context context_;
  std::shared_ptr<const world::station> station_;
  std::unique_ptr<gl_objects> gl_;
  std::vector<box_instance> boxes_;         // reused between frames
  std::vector<box_instance> second_boxes_;  // the second field's
};

}  // namespace argus::vision
