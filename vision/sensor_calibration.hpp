#pragma once

// Calibration of the emulated sensor against the pixel pipeline (`argus vision calibrate`):
// trials of both on the same frames, and the fit of sensor_model to the pixel trials.

#include <span>
#include <string>
#include <vector>

#include "opencv2/core.hpp"
#include "vision/emulated_sensor.hpp"
#include "vision/kernel_scales.hpp"
#include "vision/sensor_model.hpp"

namespace argus::vision {

/// One attempt to find one visible pedestrian in one frame, and how it went.
struct calibration_trial {
  /// The pedestrian's hidden fraction and image height (pixels).
  double occlusion = 0.0;
  double height_px = 0.0;
  /// Largest normalised histogram intersection with another pedestrian in view (0 if none).
  double similarity = 0.0;
  /// Nothing found, or a box on no pedestrian.
  bool missed = false;
  /// A box on another pedestrian (an identity swap).
  bool confused = false;
  /// Acceptance score of the box found (0 when missed).
  double score = 0.0;
  /// Distance of the found box's centre from the true one, as a fraction of the true height
  /// (hits only).
  double centre_error = 0.0;
};

/// The pixel pipeline on one rendered frame (CV_8UC3 BGR, already through the imaging
/// model): for every pedestrian of visible_pedestrians(), its appearance_signature() is
/// backprojected (T scaled to its true box area, as the tracker does) and the first region of
/// the multiscale localiser (rho = `rho`) is compared with the true boxes: its centre inside
/// the pedestrian's box is a hit, inside another's (nearest first) a confusion, else a miss.
/// The localiser's kernels are kernel_scales(`scales`) around the pedestrian's true box, the
/// size a tracker knows from its last box.
std::vector<calibration_trial> pixel_trials(const cv::Mat& frame_bgr, const world::snapshot& frame,
                                            const world::station& where, const camera_view& view,
                                            double rho = 0.4, const scale_settings& scales = {});

/// The same trials answered by the emulated sensor's look_for().
std::vector<calibration_trial> emulated_trials(emulated_sensor& sensor,
                                               const world::snapshot& frame,
                                               const world::station& where,
                                               const camera_view& view);

/// Fits the miss and confusion logistic models (Newton's method, lightly regularised) and
/// the box and confidence statistics to `trials`; the hard limits (max_occlusion,
/// min_height_px) are kept from `start`.
sensor_model fit_sensor_model(std::span<const calibration_trial> trials, sensor_model start = {});

/// Rates over trials: misses among those within the model's hard limits, confusions among
/// those found.
struct trial_rates {
  double miss = 0.0;
  double confusion = 0.0;
  int trials = 0;
};

/// The miss and confusion rates of `trials`.
trial_rates rates_of(std::span<const calibration_trial> trials);

/// A text table of miss rate by occlusion and by image height, and confusion rate by
/// similarity, for the log.
std::string describe(std::span<const calibration_trial> trials);

}  // namespace argus::vision
