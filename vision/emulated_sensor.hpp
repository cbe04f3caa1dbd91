#pragma once

// The emulated sensor: what the pixel pipeline (render, imaging model, backprojection,
// multiscale localisation) would report, produced from ground truth through an error model,
// for runs with thousands of cameras (issue 5).

#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "opencv2/core.hpp"
#include "vision/color_histogram.hpp"
#include "vision/ptz_camera.hpp"
#include "vision/sensor_model.hpp"
#include "world/pedestrian.hpp"
#include "world/rng.hpp"

namespace argus::world {
class snapshot;
class station;
}  // namespace argus::world

namespace argus::vision {

/// The appearance signature of a pedestrian from its true colours: shirt, trousers, skin and
/// hair by their share of a standing figure, each at three shading levels (lit, half-lit,
/// shaded) as the renderer's Lambert lighting spreads them. The emulated sensor's
/// signatures, and the target histograms of the calibration's pixel pipeline.
color_histogram appearance_signature(const world::appearance& look,
                                     const histogram_bins& bins = {});

/// How one pedestrian appears in a camera's image (simulator knowledge, never a node's).
struct pedestrian_view {
  /// The pedestrian's id.
  int id = 0;
  /// The projected body box, not clipped to the image (pixels, x and y the top-left).
  cv::Rect2d box;
  /// Distance along the optical axis to the body's centre, metres.
  double depth_m = 0.0;
  /// Fraction of the box hidden by the image edges or nearer pedestrians, in [0, 1].
  double occlusion = 0.0;
};

/// Whether the straight line from `a` to `b` on the plan crosses no wall of `where`.
bool wall_free(const world::station& where, const world::vec2& a, const world::vec2& b);

/// Every pedestrian of `frame` that `view` can see at least partly: in front of the camera,
/// its box overlapping the image, and no wall of `where` on the line from the camera to it
/// (station::line_clear). Nearest first. Occlusion is measured on a 6 x 18 grid of points of
/// each box: those outside the image or inside the box of a nearer pedestrian are hidden.
std::vector<pedestrian_view> visible_pedestrians(const world::snapshot& frame,
                                                 const world::station& where,
                                                 const camera_view& view);

/// One detection, as the pixel pipeline reports it.
struct sensor_detection {
  /// Box in pixels, clipped to the image.
  cv::Rect box;
  /// Appearance signature of what the box shows (sent in queryrelevance).
  color_histogram signature;
  /// Acceptance score (histogram intersection, Fig. 9 step 5), in [0, 1].
  double confidence = 0.0;
  /// Ground truth: whom the box shows. For evaluation only; a camera node must not use it.
  int pedestrian_id = -1;
};

/// The result of looking for one target (the tracker's update() in pixels).
struct sensor_observation {
  /// False when the track is lost in this frame.
  bool found = false;
  /// The detection reported as the target (empty box when not found).
  sensor_detection detection;
  /// Whether the reported box shows another pedestrian (an identity swap). Ground truth.
  bool confused = false;
};

/// The emulated sensor of one camera. Draws from its own RNG, seeded per camera
/// (config::derive_seed), so a camera's errors are the same in every run with the same
/// seed, whichever thread steps it. Not thread-safe: one per camera.
class emulated_sensor {
 public:
  /// A sensor with error model `model`, drawing from `seed`.
  emulated_sensor(sensor_model model, std::uint64_t seed, histogram_bins bins = {});

  /// The sensor of camera `camera_id` in a run seeded with `run_seed`.
  static emulated_sensor for_camera(sensor_model model, std::uint64_t run_seed, int camera_id);

  /// Every pedestrian the camera detects in `frame`: each visible pedestrian not missed
  /// (P(miss) of sensor_model), with a noisy box, its signature and a confidence.
  std::vector<sensor_detection> detect(const world::snapshot& frame, const world::station& where,
                                       const camera_view& view);

  /// Looks for pedestrian `target_id`: missed as in detect(); otherwise, with P(confusion)
  /// from the most similar other pedestrian in view, that one's box is reported instead.
  sensor_observation look_for(int target_id, const world::snapshot& frame,
                              const world::station& where, const camera_view& view);
  /// look_for() given what the camera sees: `seen` is visible_pedestrians(frame, where, view).
  sensor_observation look_for(int target_id, const world::snapshot& frame,
                              std::span<const pedestrian_view> seen, const camera_view& view);

  /// P(miss) for a pedestrian with `occlusion` and an image height of `height_px`.
  double miss_probability(double occlusion, double height_px) const;

  /// P(confusion) given the largest similarity to another pedestrian in view.
  double confusion_probability(double similarity) const;

  /// The error model.
  const sensor_model& model() const noexcept { return model_; }

 private:
  sensor_detection make_detection(const pedestrian_view& seen, const world::snapshot& frame,
                                  const camera_view& view);
  const color_histogram& signature_of(const world::pedestrian_state& who);
  double normal() noexcept;

  sensor_model model_;
  histogram_bins bins_;
  world::rng random_;
  // Signatures by appearance, cached: palettes are small, so few distinct ones.
  // A deque: signature_of hands out references that must survive later insertions.
  std::deque<std::pair<world::appearance, color_histogram>> signatures_;
};

}  // namespace argus::vision
