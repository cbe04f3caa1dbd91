#pragma once

// A signature in two halves: the colours of the upper and of the lower half of a person's box,
// each a histogram of its own. One histogram of the whole box cannot tell a red shirt over
// blue trousers from a blue shirt over red trousers, nor either from a patch of floor that
// happens to hold both colours; the halves can. In the station's runs they do not help: the
// strangers the cameras take are not her colours the other way up, and the halves refuse her
// zoomed-in views as often as strangers (bench/RESULTS.md, "an identity test in halves").

#include <opencv2/core.hpp>

#include "vision/color_histogram.hpp"

namespace argus::vision {

/// The two regions of a person's box the halves are taken from: the upper from an eighth of
/// its height down (below the head and hair, which most people share in colour) to the middle,
/// the lower from the middle to the bottom. Both at least one row when the box is.
struct box_halves {
  cv::Rect upper;
  cv::Rect lower;
};

/// The halves of `box`.
box_halves halves_of(const cv::Rect& box);

/// A pedestrian's appearance in halves, each histogram normalised to sum 1.
struct signature_halves {
  color_histogram upper;
  color_histogram lower;
};

/// The halves of `box` in a bin-index image (bin_index_image() with `bins`), clipped to it.
signature_halves halves_in(const cv::Mat& bin_indices, const cv::Rect& box,
                           const histogram_bins& bins);

/// The bins halves are compared in: hue as fine as the signature's, saturation in half as many
/// bins, brightness not at all. A half of a box 10-40 px tall holds 20-400 pixels, too few to
/// fill a signature's 256 bins alike twice; and her brightness changes more than her colours
/// between a camera's first wide look and its zoomed one (bench/RESULTS.md, "an identity test
/// in halves").
histogram_bins halves_comparison_bins(const histogram_bins& signature_bins);

/// `histogram` with its bins merged into the coarser `bins` (each channel's count at most the
/// histogram's): a bin goes to the coarse bin that covers the same part of each channel.
color_histogram merged_into(const color_histogram& histogram, const histogram_bins& bins);

/// `signature` and `seen` blended half by half as signature_update blends a model (blended()):
/// what a tracker that re-takes its model from its own pixels (signature_update) tests
/// halves against, so that her halves zoomed in are compared with her zoomed in.
signature_halves blended_halves(const signature_halves& signature, const signature_halves& seen,
                                double own_weight);

/// How well `seen` matches `model`: the smaller of the two halves' histogram intersections
/// (normalised by the model) in halves_comparison_bins(), so that both must match: in [0, 1],
/// 0 when any half is empty.
double halves_match(const signature_halves& model, const signature_halves& seen);

}  // namespace argus::vision
