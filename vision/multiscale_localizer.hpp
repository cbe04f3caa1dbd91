#pragma once

// Target localisation in backprojected images: the paper's multiscale algorithm (Fig. 9)
// and Swain and Ballard's single-scale baseline [45].
//
// Kernel shape. The paper uses "(6l + 1) x (2l + 1) rectangular summing kernels"; we read
// the first factor as the height and the second as the width (rows x columns, the usual
// image convention), so that a kernel is tall and thin like a standing pedestrian
// (Fig. 9(a) shows upright targets). The kernel of size l covers the rows y - 3l .. y + 3l
// and the columns x - l .. x + l around its centre (x, y). The image is extended with zero
// borders, as in Fig. 8.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "opencv2/core.hpp"
#include "vision/color_histogram.hpp"
#include "vision/kernel_scales.hpp"

namespace argus::vision {

/// A localised target: its box in pixels (x, y the top-left corner, clipped to the image),
/// its acceptance score (Fig. 9, step 5) and the kernel size l that produced it.
struct localized_region {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
  double score = 0.0;
  int scale = 0;
  /// The box as a cv::Rect.
  cv::Rect box() const { return {x, y, width, height}; }
};

/// Scores a candidate box for acceptance (Fig. 9, step 5); accepted if the score > rho.
using region_scorer = std::function<double(const cv::Rect&)>;

/// The paper's acceptance test: the intersection of the target histogram with the histogram
/// of the box in the original image, sum_i min(T(i), H(i)) / sum_i T(i) (Fig. 9, step 5),
/// both normalised to sum 1 so that boxes of any size compare with the same T. `bin_indices`
/// is bin_index_image() of the original image; both must outlive the scorer.
region_scorer histogram_scorer(const cv::Mat& bin_indices, const color_histogram& target);

/// The domain of the (6l + 1) x (2l + 1) kernel of size l centred at `centre` (not clipped).
cv::Rect kernel_domain(cv::Point centre, int l);

/// B_l = B * K_l (Fig. 9, step 1) with zero borders, by a direct double loop. Slow; a
/// reference for tests. l = 0 is the 1 x 1 kernel.
cv::Mat box_response_reference(const cv::Mat& backprojection, int l);

/// How step 4 of Fig. 9 picks the kernel size l* at the peak (x*, y*): the paper's sharpest
/// response, or by the acceptance test of step 5 (the largest size whose box scores within
/// 3 % of the best). On real video
/// the sharpness favours the largest kernel of any range (each kernel's sums grow with its area
/// over cluttered backgrounds, and so do their differences): over sizes from half to twice a
/// person's it gave boxes twice her area, missing 78 % of searches where the acceptance score
/// missed 17 % (bench/RESULTS.md, issue 19).
enum class scale_choice { sharpness, score };

/// Settings of the localiser.
struct localizer_settings {
  /// Kernel sizes l (each >= 0); empty = paper_scales(frame height).
  std::vector<int> scales;
  /// Acceptance threshold rho on the score (Fig. 9, step 5).
  double rho = 0.5;
  /// At most this many regions per call (the paper repeats until the first rejection).
  int max_regions = 16;
  /// How step 4 picks the kernel size.
  scale_choice choice = scale_choice::sharpness;
  /// With scale_choice::score: the kernel size expected (> 0), e.g. a tracker's last box
  /// carried along with the camera's motion; of the sizes scoring near the best, the nearest
  /// to it wins instead of the largest. 0: the largest.
  double expected_scale = 0.0;
};

/// The localiser's settings under `scales` for a frame `frame_height_px` high and a target
/// expected to be `target` (if known): kernel_scales(), and step 4 by the acceptance score
/// under scale_rule::target (by the paper's sharpness under scale_rule::paper).
localizer_settings localizer_settings_for(const scale_settings& scales,
                                          const std::optional<cv::Size2d>& target,
                                          int frame_height_px, double rho, int max_regions);

/// The multiscale localiser of Fig. 9. Keeps its buffers between calls; not thread-safe, one
/// per camera. With a single scale it is Swain and Ballard's localisation [45].
class multiscale_localizer {
 public:
  /// A localiser with `settings`.
  explicit multiscale_localizer(localizer_settings settings = {});

  /// Every target in the CV_32F backprojection B, in the order found: Fig. 9, steps 1-6,
  /// repeated until the first rejection (score <= rho), an empty B, or max_regions.
  ///
  /// Step 1: B_l = B * K_l for every l, by box sums over one integral image of B (evaluated
  ///         where needed: summed over l in the 32 x 16 tiles whose upper bound reaches the
  ///         peak when B >= 0, in every tile otherwise; per l only near the peak).
  /// Step 2: (x*, y*) = argmax sum_l B_l.
  /// Step 3: per l, the peak (x_l*, y_l*) of B_l inside K_l centred at (x*, y*).
  /// Step 4: l* = argmax_l sum_{K}(B_l(x_l*, y_l*) - B_l(x, y))^2 / |K|, over K clipped to
  ///         the image (with scale_choice::score instead: the largest l whose box centred at
  ///         (x*, y*) scores at least 0.97 max_l score, and steps 3 and 4 are not computed).
  /// Step 5: the box of size l* centred at (x*, y*) is accepted if score(box) > rho.
  /// Step 6: the box is set to 0 and steps 1-5 are repeated. We zero it in B and recompute
  ///         the B_l around it (only where a kernel reaches it): "remove from B_l ... repeat
  ///         steps 1 through 6" re-runs step 1, which only a change to B survives, and it
  ///         also removes the tails a large kernel would keep of the found target. Points
  ///         inside a box already accepted are not chosen again.
  ///
  /// The results are those of evaluating every step everywhere, bit for bit (see
  /// tests/vision/multiscale_localizer_equivalence_test.cpp).
  std::vector<localized_region> localize(const cv::Mat& backprojection, const region_scorer& score);

  /// The settings in use.
  const localizer_settings& settings() const noexcept { return settings_; }

  /// The B_l of the last localize() call after all removals, one per scale (for tests).
  /// Computed on demand from the final integral image.
  const std::vector<cv::Mat>& responses() const;

 private:
  void update_integral(cv::Mat& integral, const cv::Mat* previous, int first_row, int first_col,
                       int last_row);
  const double* row(std::size_t version, int y) const;
  void compute_sum(std::size_t version, const cv::Rect& area);
  void compute_tile(std::size_t tile, const std::vector<localized_region>& found);
  void bound_tiles();
  cv::Point find_peak(const std::vector<localized_region>& found, float& best);
  void compute_response(int l, const cv::Rect& area, float* out) const;

  localizer_settings settings_;
  std::vector<int> scales_;
  int pad_x_ = 0;
  // B with the accepted boxes zeroed (step 6).
  cv::Mat work_;
  // integrals_[m]: the integral image of work_ after m removals, between zero borders of
  // pad_x_ columns. Earlier ones are kept: a point's sum is the one from the integral image of
  // the last removal whose kernels reached it.
  std::vector<cv::Mat> integrals_;
  std::size_t removals_ = 0;
  // Running sums along each row of work_, a step of the integral image.
  cv::Mat prefix_;
  // Filled by responses() on demand.
  mutable std::vector<cv::Mat> responses_;
  // sum_l B_l (step 2), valid in the tiles computed so far.
  cv::Mat sum_;
  // Per removal m + 1, the points whose kernels reach the removed box.
  std::vector<cv::Rect> affected_;
  // Tiles of the summed response: an upper bound of the sum in each, whether it is computed
  // and then its maximum. A tile is computed only if its bound reaches the peak.
  int tiles_x_ = 0;
  int tiles_y_ = 0;
  bool bounded_ = false;
  // Whether all sums of the integral image are exact (see localize()).
  bool exact_ = false;
  std::vector<double> tile_bound_;
  std::vector<float> tile_max_;
  std::vector<std::uint8_t> tile_done_;
  std::vector<int> tile_order_;
  // Steps 3 and 4: B_l over its kernel domain for every l, one after the other.
  std::vector<float> domain_responses_;
  // Step 4 with scale_choice::score: each size's score.
  std::vector<double> scores_;
};

/// Swain and Ballard's single-scale localisation [45] with the (6l + 1) x (2l + 1) kernel of
/// size l: peaks of B_l, each accepted by `score` > rho and removed, as above.
std::vector<localized_region> localize_single_scale(const cv::Mat& backprojection, int l,
                                                    const region_scorer& score, double rho = 0.5,
                                                    int max_regions = 16);

}  // namespace argus::vision
