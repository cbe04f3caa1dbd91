#pragma once

// A tracker's model of its target, re-taken from its own camera's pixels. The signature a
// track starts from was taken from a box a few pixels wide (at the tasking camera's wide view,
// or by another camera with another colour response): zoomed in, her pixels no longer look
// like it (her score falls from 0.6-0.8 to 0.41-0.47, barely above rho = 0.4, while large
// boxes of floor score about 0.42), and the box grows over the floor and drifts off her
// (bench/RESULTS.md, issue 15). Once the track has held her in its search window for a few
// frames in a row, the camera's own view of her is the better model; blended with the
// signature, so that one bad frame cannot make the model someone else altogether.

#include "opencv2/core.hpp"
#include "vision/color_histogram.hpp"

namespace argus::vision {

/// When and how a tracker re-takes its model.
struct signature_update_settings {
  /// Frames in a row the target must be found in the search window (not by a whole-frame
  /// search) before her box is trusted to be her.
  int confirm_frames = 5;
  /// The model is taken again when her box's height has changed by this factor since it was
  /// last taken (a zoom, or her walking nearer or away).
  double height_change = 1.4;
  /// The weight of the camera's own view in the model; the signature has the rest.
  double own_weight = 0.5;
  /// The part of the box taken: this fraction of its width and of its height about its centre
  /// (her torso and legs; less of the floor beside her).
  double core_width = 0.5;
  double core_height = 0.8;
};

/// The central part of `box` that `settings` takes (at least one pixel).
cv::Rect body_core(const cv::Rect& box, const signature_update_settings& settings);

/// Whether a track confirmed for `confirmed_frames` frames, with its box `box_height_px` high,
/// should take its model again; `model_height_px` is the height it was last taken at, 0 if
/// never (the model is still the signature as received).
bool model_due(int confirmed_frames, int box_height_px, int model_height_px,
               const signature_update_settings& settings);

/// `signature` and `own` normalised and blended, `own_weight` of `own`, normalised: the
/// signature alone (normalised) when `own` is empty or has other bins.
color_histogram blended(const color_histogram& signature, const color_histogram& own,
                        double own_weight);

/// The model: the normalised signature and the normalised histogram of `box`'s core in the
/// bin-index image, blended by own_weight, normalised.
color_histogram blended_model(const color_histogram& signature, const cv::Mat& bin_indices,
                              const cv::Rect& box, const signature_update_settings& settings);

}  // namespace argus::vision
