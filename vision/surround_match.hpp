#pragma once

// A figure-ground test for a tracker's box: how much the box's colours match those of a ring
// around it.

#include <array>
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

/// The same ring cut into its four sides, each matched with `box` on its own: left and right
/// (the box's rows), above and below (the ring's full width). A side clipped away by the
/// image is -1. A figure stands out against at least some of its sides (the floor at her feet)
/// even where her neighbours look like her, or where the ring holds her own arms; a patch of
/// background matches the sides all round.
std::array<double, 4> surround_side_matches(const cv::Mat& bin_indices, const cv::Rect& box,
                                            const histogram_bins& bins);

/// How many of surround_side_matches() exceed `threshold`.
int sides_matching(const std::array<double, 4>& sides, double threshold);

/// Whether `sides` (surround_side_matches()) say background: `required` of them exceed
/// `threshold`, or all of those inside the image where fewer are (a box in a corner has two).
bool background_by_sides(const std::array<double, 4>& sides, double threshold, int required);

}  // namespace argus::vision
