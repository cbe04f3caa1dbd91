#pragma once

// A figure-ground test for a tracker's box: how much the box's colours match those of a ring
// around it.

#include <opencv2/core.hpp>

#include "vision/color_histogram.hpp"

namespace argus::vision {

/// The normalised histogram intersection of `box` with the ring around it: `box` widened by
/// half its width on either side and a quarter of its height above and below (at least 2 px
/// each), without the box itself, clipped to the image. `bin_indices` is bin_index_image() with
/// `bins`. A person is a figure against the floor and walls around her and matches her ring
/// little; a patch of wall or floor matches its ring much more (bench/RESULTS.md, "a box that
/// matches its surround"). 0 when the box or the ring is empty.
double surround_match(const cv::Mat& bin_indices, const cv::Rect& box, const histogram_bins& bins);

}  // namespace argus::vision
