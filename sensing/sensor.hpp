#pragma once

// How a camera node senses: one interface for its pixels (pixel_sensing) and for the emulated
// sensor (emulated_sensing), so that the node calls one sensor whichever is in use and
// instruments can wrap it (eval/).

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "controller/controller_io.hpp"
#include "opencv2/core/mat.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::world {
class snapshot;
class station;
}  // namespace argus::world

namespace argus::sensing {

/// One frame as a sensor takes it: the camera's view, its image when rendered (empty when
/// sensing is emulated or the rendering failed), and the world it shows (simulator side: the
/// emulated sensor and instruments read it; nothing of it reaches a strategy but boxes).
struct sensed_frame {
  std::int64_t tick = 0;
  vision::camera_view view;
  cv::Mat image;
  std::shared_ptr<const world::snapshot> truth;
  std::shared_ptr<const world::station> station;
};

/// A region a sensor weighs as task `task`'s target: its box in the frame (pixels), or the
/// pedestrian it stands for (emulated sensing, which works from ground truth; 0 otherwise).
struct candidate {
  controller::task_id task = 0;
  std::optional<cv::Rect2d> box;
  int pedestrian = 0;
};

/// Whether a candidate may be taken; an empty filter takes everything.
using candidate_filter = std::function<bool(const candidate&)>;

/// A camera node's sensor.
class sensor {
 public:
  virtual ~sensor() = default;

  /// Whether it needs the frame's image (the node has it rendered).
  virtual bool needs_image() const = 0;

  /// Looks for every requested target in `frame`; forgets targets no longer asked for. With
  /// `admit`, a candidate it refuses is passed over for the next one (or none).
  virtual std::vector<controller::look_result> look(
      const sensed_frame& frame, const std::vector<controller::look_request>& looks,
      const candidate_filter& admit = {}) = 0;

  /// Whether `frame` has what a signature is taken from (an image, for pixels).
  virtual bool can_acquire(const sensed_frame& frame) const = 0;

  /// The pedestrian in `box` of `frame` becomes task `task`'s target: her signature, and the
  /// sensor follows her from there.
  virtual protocol::signature acquire(controller::task_id task, const sensed_frame& frame,
                                      const cv::Rect2d& box) = 0;
};

/// A sensor that passes everything to another, for instruments (eval/): override what it
/// changes and call the inner one.
class sensor_wrapper : public sensor {
 public:
  explicit sensor_wrapper(std::unique_ptr<sensor> inner) : inner_(std::move(inner)) {}
  bool needs_image() const override { return inner_->needs_image(); }
  std::vector<controller::look_result> look(const sensed_frame& frame,
                                            const std::vector<controller::look_request>& looks,
                                            const candidate_filter& admit = {}) override {
    return inner_->look(frame, looks, admit);
  }
  bool can_acquire(const sensed_frame& frame) const override { return inner_->can_acquire(frame); }
  protocol::signature acquire(controller::task_id task, const sensed_frame& frame,
                              const cv::Rect2d& box) override {
    return inner_->acquire(task, frame, box);
  }

 protected:
  sensor& inner() { return *inner_; }

 private:
  std::unique_ptr<sensor> inner_;
};

/// Both filters: `first` is asked first, `second` only about what `first` admits.
candidate_filter both(candidate_filter first, candidate_filter second);

}  // namespace argus::sensing
