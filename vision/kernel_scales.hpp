#pragma once

// The kernel sizes l of the multiscale localiser (Fig. 9): which (6l + 1) x (2l + 1) boxes it
// tries. The paper ties them to the frame height, (0.1 ... 1) x h / 7, which suits its frames
// but not a person 60 px tall in a 576-row frame (kernels 49-493 rows) nor a distant pedestrian
// at default zoom. By default they follow the target instead: a range around the size the
// searcher expects, from the target patch or the tracker's last box.

#include <optional>
#include <vector>

#include "opencv2/core.hpp"

namespace argus::vision {

/// Where the kernel sizes come from: around the target's expected size (the default) or the
/// paper's fractions of the frame height.
enum class scale_rule { target, paper };

/// How the localiser picks its kernel sizes.
struct scale_settings {
  /// The rule; `paper` also applies whenever the target's size is not known.
  scale_rule rule = scale_rule::target;
  /// The paper's divisor d of l = (0.1 ... 1) x h / d (7 in the paper).
  double paper_divisor = 7.0;
  /// The target's height may be from size / span to size x span. Two covers a person walking
  /// 3 s toward or away from a camera 6 m or more away (1.4 m/s: the distance changes by at
  /// most 4.2 m, a factor of 1.7 at 6 m), and a patch cut a little loose or tight.
  double span = 2.0;
  /// Kernel sizes per doubling of the height: 4 steps of 19 %, so that the nearest kernel is
  /// within 10 % of any height in the span.
  int steps_per_octave = 4;
};

/// The kernel sizes l = (0.1, 0.2, ..., 1) x h / 7 for a frame h pixels high, each rounded
/// to the nearest integer and at least 1, duplicates removed (Section III-B). With another
/// `divisor` d, l = (0.1, ..., 1) x h / d: the largest kernel, 6 h / d + 1 rows, is 86 % of
/// the frame height at the paper's d = 7, taller than any pedestrian a wide view shows; a
/// larger d (e.g. 28) suits small pedestrians. Throws std::invalid_argument unless d > 0.
std::vector<int> paper_scales(int frame_height_px, double divisor = 7.0);

/// The kernel size whose (6l + 1) x (2l + 1) box holds as many pixels as a `size` box (at least
/// 0): a patch or box of any aspect maps to the kernel that sums as much of it.
double kernel_size_for(const cv::Size2d& size);

/// Kernel sizes for a target expected to be `size` (pixels): the sizes for heights from
/// size / span to size x span in steps of 2^(1 / steps_per_octave), rounded, at least 1 and
/// at most the largest kernel that fits the frame (6l + 1 <= `frame_height_px`), ascending,
/// duplicates removed. Throws std::invalid_argument unless span >= 1 and steps_per_octave >= 1.
std::vector<int> target_scales(const cv::Size2d& size, int frame_height_px,
                               const scale_settings& settings = {});

/// The kernel sizes `settings` gives for a frame `frame_height_px` high: target_scales()
/// around `target` under the target rule when it is known and not empty, else paper_scales().
std::vector<int> kernel_scales(const scale_settings& settings,
                               const std::optional<cv::Size2d>& target, int frame_height_px);

}  // namespace argus::vision
