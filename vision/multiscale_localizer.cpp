#include "vision/multiscale_localizer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

#include "fmt/format.h"
#include "opencv2/imgproc.hpp"

namespace argus::vision {
namespace {

// Below this, the summed response counts as empty (rounding residue of the integral image).
constexpr double empty_response = 1e-6;
// Marks points of the summed response inside an accepted box (B >= 0, so sums are >= 0).
constexpr float suppressed = -1.0f;

}  // namespace

region_scorer histogram_scorer(const cv::Mat& bin_indices, const color_histogram& target) {
  return [&bin_indices, normalized_target = target.normalized()](const cv::Rect& box) {
    auto candidate = color_histogram::of_bin_indices(bin_indices, box, normalized_target.bins());
    return intersection(normalized_target, candidate.normalized());
  };
}

std::vector<int> paper_scales(int frame_height_px, double divisor) {
  if (!(divisor > 0.0))
    throw std::invalid_argument(fmt::format("paper_scales: divisor must be > 0, not {}", divisor));
  std::vector<int> scales;
  for (int k = 1; k <= 10; ++k) {
    int l = static_cast<int>(std::lround(0.1 * k * frame_height_px / divisor));
    l = std::max(l, 1);
    if (scales.empty() || scales.back() != l) scales.push_back(l);
  }
  return scales;
}

cv::Rect kernel_domain(cv::Point centre, int l) {
  return {centre.x - l, centre.y - 3 * l, 2 * l + 1, 6 * l + 1};
}

cv::Mat box_response_reference(const cv::Mat& backprojection, int l) {
  CV_Assert(backprojection.type() == CV_32F && l >= 0);
  cv::Mat result(backprojection.size(), CV_32F);
  const cv::Rect image(0, 0, backprojection.cols, backprojection.rows);
  for (int y = 0; y < backprojection.rows; ++y)
    for (int x = 0; x < backprojection.cols; ++x) {
      auto domain = kernel_domain({x, y}, l) & image;
      result.at<float>(y, x) = static_cast<float>(cv::sum(backprojection(domain))[0]);
    }
  return result;
}

multiscale_localizer::multiscale_localizer(localizer_settings settings)
    : settings_(std::move(settings)) {
  // nop
}

// The integral image of B extended with zero columns (work_ between pad_x_ zero columns on
// each side), from row `first_row` on; rows above it are kept:
// I(y + 1, x + 1) = I(y, x + 1) + sum_{x' <= x} P(y, x'), accumulated in double. The zero
// rows above and below B are not stored: row() clamps to rows 0 and height, whose sums they
// equal. The side columns add only zeros, so they are filled by copying instead of summing.
// Rows are computed the same way from scratch and after a removal, so the incremental
// update of step 6 gives bit-identical sums to a full recomputation.
void multiscale_localizer::update_integral(int first_row) {
  const int width = work_.cols;
  const int height = work_.rows;
  const int cols = width + 2 * pad_x_ + 1;
  if (first_row == 0) {
    integral_.create(height + 1, cols, CV_64F);
    std::fill_n(integral_.ptr<double>(0), cols, 0.0);
  }
  // Pass 1: each row's running sums, four rows at a time so that their add chains overlap.
  prefix_.create(height, width, CV_64F);
  int y = first_row;
  for (; y + 4 <= height; y += 4) {
    const float* in[4];
    double* out[4];
    double row_sum[4] = {0.0, 0.0, 0.0, 0.0};
    for (int r = 0; r < 4; ++r) {
      in[r] = work_.ptr<float>(y + r);
      out[r] = prefix_.ptr<double>(y + r);
    }
    for (int x = 0; x < width; ++x)
      for (int r = 0; r < 4; ++r) out[r][x] = row_sum[r] += in[r][x];
  }
  for (; y < height; ++y) {
    const float* in = work_.ptr<float>(y);
    double* out = prefix_.ptr<double>(y);
    double row_sum = 0.0;
    for (int x = 0; x < width; ++x) out[x] = row_sum += in[x];
  }
  // Pass 2: I(y + 1, x + 1) = I(y, x + 1) + running sum.
  for (y = first_row; y < height; ++y) {
    const double* __restrict sums = prefix_.ptr<double>(y);
    const double* __restrict above = integral_.ptr<double>(y) + pad_x_ + 1;
    double* __restrict out = integral_.ptr<double>(y + 1);
    std::fill_n(out, pad_x_ + 1, 0.0);
    out += pad_x_ + 1;
    for (int x = 0; x < width; ++x) out[x] = above[x] + sums[x];
    std::fill_n(out + width, pad_x_, out[width - 1]);
  }
}

const double* multiscale_localizer::row(int y) const {
  return integral_.ptr<double>(std::clamp(y, 0, integral_.rows - 1)) + pad_x_;
}

// Fig. 9, steps 1 and 2 for the pixels in `area`: sum_l B_l(x, y), each B_l(x, y) a box sum
// over the integral image (four look-ups), rounded to float and added in scale order. The
// B_l themselves are not stored: steps 3 and 4 need them only near the peak. This loop is
// most of the localiser's time; an AVX2 clone (picked at load time where the CPU has it)
// does four box sums at once with the same operations, hence the same results.
#if defined(__GNUC__) && defined(__x86_64__)
__attribute__((target_clones("avx2", "default")))
#endif
void multiscale_localizer::compute_sum(const cv::Rect& area) {
  for (int y = area.y; y < area.y + area.height; ++y) {
    float* __restrict sum = sum_.ptr<float>(y) + area.x;
    std::fill_n(sum, area.width, 0.0f);
    for (const int l : scales_) {
      const double* __restrict top = row(y - 3 * l) + area.x;
      const double* __restrict bottom = row(y + 3 * l + 1) + area.x;
      for (int x = 0; x < area.width; ++x)
        sum[x] +=
            static_cast<float>((bottom[x + l + 1] - bottom[x - l]) - (top[x + l + 1] - top[x - l]));
    }
  }
}

// B_l over `area` into `out` (CV_32F, area.size()), as compute_sum() evaluates it.
void multiscale_localizer::compute_response(int l, const cv::Rect& area, cv::Mat& out) const {
  out.create(area.height, area.width, CV_32F);
  for (int y = area.y; y < area.y + area.height; ++y) {
    const double* top = row(y - 3 * l) + area.x;
    const double* bottom = row(y + 3 * l + 1) + area.x;
    float* row = out.ptr<float>(y - area.y);
    for (int x = 0; x < area.width; ++x)
      row[x] =
          static_cast<float>((bottom[x + l + 1] - bottom[x - l]) - (top[x + l + 1] - top[x - l]));
  }
}

const std::vector<cv::Mat>& multiscale_localizer::responses() const {
  if (responses_.size() != scales_.size()) {
    responses_.resize(scales_.size());
    for (std::size_t k = 0; k < scales_.size(); ++k)
      compute_response(scales_[k], cv::Rect(0, 0, work_.cols, work_.rows), responses_[k]);
  }
  return responses_;
}

std::vector<localized_region> multiscale_localizer::localize(const cv::Mat& backprojection,
                                                             const region_scorer& score) {
  CV_Assert(backprojection.type() == CV_32F);
  std::vector<localized_region> found;
  responses_.clear();
  const int width = backprojection.cols;
  const int height = backprojection.rows;
  backprojection.copyTo(work_);
  if (width == 0 || height == 0) return found;
  scales_ = settings_.scales.empty() ? paper_scales(height) : settings_.scales;
  const int largest = *std::max_element(scales_.begin(), scales_.end());
  CV_Assert(*std::min_element(scales_.begin(), scales_.end()) >= 0);
  pad_x_ = largest + 1;
  const cv::Rect image(0, 0, width, height);
  update_integral(0);
  sum_.create(height, width, CV_32F);

  // Step 1 (all of the image) and the sum for step 2.
  compute_sum(image);

  while (static_cast<int>(found.size()) < settings_.max_regions) {
    // Step 2: the peak of the summed response.
    double best = 0.0;
    cv::Point centre;
    cv::minMaxLoc(sum_, nullptr, &best, nullptr, &centre);
    if (best <= empty_response) break;

    // Steps 3 and 4: per scale, the peak inside the kernel domain and its sharpness.
    int best_scale = scales_.front();
    double best_sharpness = -1.0;
    for (const int l : scales_) {
      const auto domain = kernel_domain(centre, l) & image;
      compute_response(l, domain, scratch_);
      double peak = 0.0;
      cv::minMaxLoc(scratch_, nullptr, &peak);
      double squares = 0.0;
      for (int y = 0; y < scratch_.rows; ++y) {
        const float* row = scratch_.ptr<float>(y);
        for (int x = 0; x < scratch_.cols; ++x) {
          double d = peak - row[x];
          squares += d * d;
        }
      }
      double sharpness = squares / domain.area();
      if (sharpness > best_sharpness) {
        best_sharpness = sharpness;
        best_scale = l;
      }
    }

    // Step 5: accept the box of size l* centred at (x*, y*) by its score.
    const auto box = kernel_domain(centre, best_scale) & image;
    const double box_score = score(box);
    if (!(box_score > settings_.rho)) break;
    found.push_back({box.x, box.y, box.width, box.height, box_score, best_scale});

    // Step 6: remove the box from B and recompute the sum where a kernel reaches it. Only
    // integral rows from the box's top down change.
    work_(box).setTo(0.0f);
    update_integral(box.y);
    const cv::Rect affected = cv::Rect(box.x - largest, box.y - 3 * largest,
                                       box.width + 2 * largest, box.height + 6 * largest) &
                              image;
    compute_sum(affected);
    for (const auto& region : found) sum_(region.box()).setTo(suppressed);
  }
  return found;
}

std::vector<localized_region> localize_single_scale(const cv::Mat& backprojection, int l,
                                                    const region_scorer& score, double rho,
                                                    int max_regions) {
  multiscale_localizer localizer({{l}, rho, max_regions});
  return localizer.localize(backprojection, score);
}

}  // namespace argus::vision
