#include "vision/multiscale_localizer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <span>
#include <string_view>

#include "opencv2/imgproc.hpp"

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#define ARGUS_LOCALIZER_X86 1
#endif

namespace argus::vision {
namespace {

// The summed response is computed in tiles of this many pixels (step 2).
constexpr int tile_width = 32;
constexpr int tile_height = 16;
// Below this, the summed response counts as empty (rounding residue of the integral image).
constexpr double empty_response = 1e-6;
// With scale_choice::score, sizes whose box scores at least this fraction of the best compete,
// and the largest wins (see localize()).
constexpr double near_best_score = 0.97;
// Marks points of the summed response inside an accepted box (B >= 0, so sums are >= 0).
constexpr float suppressed = -1.0f;

// One row of box sums for one kernel size l: B_l(x, y) = (bottom_right[x] - bottom_left[x]) -
// (top_right[x] - top_left[x]), the four corners of the kernel in the integral image rows
// above (y - 3l) and below (y + 3l + 1) it, at columns x + l + 1 and x - l.
struct box_rows {
  const double* top_left;
  const double* top_right;
  const double* bottom_left;
  const double* bottom_right;
};

box_rows corners(const double* top, const double* bottom, int l) {
  return {top - l, top + l + 1, bottom - l, bottom + l + 1};
}

// out[x] = sum_k (float)B_k(x), added in k order starting from 0: sum_l B_l(x, y) along a
// row segment of `width` pixels (Fig. 9, steps 1 and 2). Every variant below does exactly
// these IEEE operations per pixel, in this order (no FMA: there is no product), so all give
// the same bits; the vector ones keep the running sums in registers across the kernel sizes.
void sum_row_default(const box_rows* rows, int count, int width, float* __restrict out) {
  for (int x = 0; x < width; ++x) out[x] = 0.0f;
  for (int k = 0; k < count; ++k) {
    const double* __restrict tl = rows[k].top_left;
    const double* __restrict tr = rows[k].top_right;
    const double* __restrict bl = rows[k].bottom_left;
    const double* __restrict br = rows[k].bottom_right;
    for (int x = 0; x < width; ++x) out[x] += static_cast<float>((br[x] - bl[x]) - (tr[x] - tl[x]));
  }
}

#ifdef ARGUS_LOCALIZER_X86

__attribute__((target("avx2"))) void sum_row_avx2(const box_rows* rows, int count, int width,
                                                  float* __restrict out) {
  int x = 0;
  for (; x + 16 <= width; x += 16) {
    __m128 sum[4] = {_mm_setzero_ps(), _mm_setzero_ps(), _mm_setzero_ps(), _mm_setzero_ps()};
    for (int k = 0; k < count; ++k) {
      const box_rows& r = rows[k];
      for (int i = 0; i < 4; ++i) {
        const int at = x + 4 * i;
        const __m256d box = _mm256_sub_pd(
            _mm256_sub_pd(_mm256_loadu_pd(r.bottom_right + at),
                          _mm256_loadu_pd(r.bottom_left + at)),
            _mm256_sub_pd(_mm256_loadu_pd(r.top_right + at), _mm256_loadu_pd(r.top_left + at)));
        sum[i] = _mm_add_ps(sum[i], _mm256_cvtpd_ps(box));
      }
    }
    for (int i = 0; i < 4; ++i) _mm_storeu_ps(out + x + 4 * i, sum[i]);
  }
  for (; x < width; ++x) {
    float sum = 0.0f;
    for (int k = 0; k < count; ++k) {
      const box_rows& r = rows[k];
      sum += static_cast<float>((r.bottom_right[x] - r.bottom_left[x]) -
                                (r.top_right[x] - r.top_left[x]));
    }
    out[x] = sum;
  }
}

// 32 pixels at a time; masked loads at the end of the segment read nothing and give 0.
__attribute__((target("avx512f"))) void sum_row_avx512(const box_rows* rows, int count, int width,
                                                       float* __restrict out) {
  int x = 0;
  for (; x + 32 <= width; x += 32) {
    __m256 sum[4] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps(),
                     _mm256_setzero_ps()};
    for (int k = 0; k < count; ++k) {
      const box_rows& r = rows[k];
      for (int i = 0; i < 4; ++i) {
        const int at = x + 8 * i;
        const __m512d box = _mm512_sub_pd(
            _mm512_sub_pd(_mm512_loadu_pd(r.bottom_right + at),
                          _mm512_loadu_pd(r.bottom_left + at)),
            _mm512_sub_pd(_mm512_loadu_pd(r.top_right + at), _mm512_loadu_pd(r.top_left + at)));
        sum[i] = _mm256_add_ps(sum[i], _mm512_maskz_cvtpd_ps(0xff, box));
      }
    }
    for (int i = 0; i < 4; ++i) _mm256_storeu_ps(out + x + 8 * i, sum[i]);
  }
  for (; x < width; x += 8) {
    const int left = width - x;
    const __mmask8 m = left >= 8 ? __mmask8(0xff) : __mmask8((1u << left) - 1);
    __m256 sum = _mm256_setzero_ps();
    for (int k = 0; k < count; ++k) {
      const box_rows& r = rows[k];
      const __m512d box = _mm512_sub_pd(_mm512_sub_pd(_mm512_maskz_loadu_pd(m, r.bottom_right + x),
                                                      _mm512_maskz_loadu_pd(m, r.bottom_left + x)),
                                        _mm512_sub_pd(_mm512_maskz_loadu_pd(m, r.top_right + x),
                                                      _mm512_maskz_loadu_pd(m, r.top_left + x)));
      sum = _mm256_add_ps(sum, _mm512_maskz_cvtpd_ps(0xff, box));
    }
    alignas(32) float sums[8];
    _mm256_store_ps(sums, sum);
    std::copy_n(sums, std::min(left, 8), out + x);
  }
}

#endif

using sum_row_function = void (*)(const box_rows*, int, int, float*);

// The fastest variant this CPU runs, picked once.
// ARGUS_LOCALIZER_SIMD=avx2 or =default caps the choice (the tests run every variant).
sum_row_function pick_sum_row() {
#ifdef ARGUS_LOCALIZER_X86
  const char* cap = std::getenv("ARGUS_LOCALIZER_SIMD");
  const std::string_view limit = cap != nullptr ? cap : "";
  __builtin_cpu_init();
  if (limit.empty() && __builtin_cpu_supports("avx512f")) return sum_row_avx512;
  if (limit != "default" && __builtin_cpu_supports("avx2")) return sum_row_avx2;
#endif
  return sum_row_default;
}

const sum_row_function sum_row = pick_sum_row();

// The largest of `values` (exact in any order; no NaN here).
float max_of(const float* values, int count) {
  float best = -std::numeric_limits<float>::infinity();
  int x = 0;
#ifdef ARGUS_LOCALIZER_X86
  __m128 lanes[4];
  for (auto& lane : lanes) lane = _mm_set1_ps(best);
  for (; x + 16 <= count; x += 16)
    for (int i = 0; i < 4; ++i) lanes[i] = _mm_max_ps(_mm_loadu_ps(values + x + 4 * i), lanes[i]);
  alignas(16) float reduced[16];
  for (int i = 0; i < 4; ++i) _mm_store_ps(reduced + 4 * i, lanes[i]);
  for (const float v : reduced) best = v > best ? v : best;
#endif
  for (; x < count; ++x) best = values[x] > best ? values[x] : best;
  return best;
}

// What localize() needs to know of B: whether every value is >= 0 (no NaN), the smallest
// positive value (infinity if none) and the largest value (0 if none is larger).
struct value_range {
  bool nonnegative = true;
  float smallest_positive = std::numeric_limits<float>::infinity();
  float largest = 0.0f;
};

value_range range_of(const cv::Mat& values) {
  value_range range;
  const float infinity = std::numeric_limits<float>::infinity();
  for (int y = 0; y < values.rows; ++y) {
    const float* row = values.ptr<float>(y);
    int x = 0;
#ifdef ARGUS_LOCALIZER_X86
    const __m128 zero = _mm_setzero_ps();
    const __m128 inf = _mm_set1_ps(infinity);
    __m128 negative = zero;
    __m128 smallest = _mm_set1_ps(range.smallest_positive);
    __m128 largest = _mm_set1_ps(range.largest);
    for (; x + 4 <= values.cols; x += 4) {
      const __m128 v = _mm_loadu_ps(row + x);
      negative = _mm_or_ps(negative, _mm_cmpnge_ps(v, zero));
      const __m128 positive = _mm_cmpgt_ps(v, zero);
      smallest =
          _mm_min_ps(_mm_or_ps(_mm_and_ps(positive, v), _mm_andnot_ps(positive, inf)), smallest);
      largest = _mm_max_ps(v, largest);
    }
    range.nonnegative = range.nonnegative && _mm_movemask_ps(negative) == 0;
    alignas(16) float lanes[8];
    _mm_store_ps(lanes, smallest);
    _mm_store_ps(lanes + 4, largest);
    for (int i = 0; i < 4; ++i) {
      range.smallest_positive =
          lanes[i] < range.smallest_positive ? lanes[i] : range.smallest_positive;
      range.largest = lanes[4 + i] > range.largest ? lanes[4 + i] : range.largest;
    }
#endif
    for (; x < values.cols; ++x) {
      const float v = row[x];
      range.nonnegative = range.nonnegative && v >= 0.0f;
      if (v > 0.0f && v < range.smallest_positive) range.smallest_positive = v;
      range.largest = v > range.largest ? v : range.largest;
    }
    if (!range.nonnegative) break;
  }
  return range;
}

// out[x] = above[x] + sums[x]: a row of the integral image (one add each, the same bits in
// every variant).
// Not under ThreadSanitizer: the clones' resolver runs while the dynamic loader relocates the
// program, before the TSan runtime is up, and its instrumented code crashes there.
#if defined(ARGUS_LOCALIZER_X86) && !defined(__SANITIZE_THREAD__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void add_rows(const double* __restrict above, const double* __restrict sums,
              double* __restrict out, int count) {
  for (int x = 0; x < count; ++x) out[x] = above[x] + sums[x];
}

// One sum of step 4: sum_i (peak - values[i])^2 over `size` values, in order.
struct chain {
  const float* values;
  std::size_t size;
  double peak;
  double squares;
};

// Advances N chains over [begin, end) in lockstep, the sums in registers.
template <std::size_t N>
void advance(chain* chains, std::size_t begin, std::size_t end) {
  double sums[N];
  for (std::size_t c = 0; c < N; ++c) sums[c] = chains[c].squares;
  for (std::size_t i = begin; i < end; ++i)
    for (std::size_t c = 0; c < N; ++c) {
      const double d = chains[c].peak - chains[c].values[i];
      sums[c] += d * d;
    }
  for (std::size_t c = 0; c < N; ++c) chains[c].squares = sums[c];
}

// Completes up to four chains sorted by decreasing size: all together up to the shortest,
// then the rest, and so on.
void advance_chains(chain* chains, std::size_t count) {
  std::size_t done = 0;
  for (std::size_t n = count; n > 0; --n) {
    const std::size_t end = chains[n - 1].size;
    if (n == 4) advance<4>(chains, done, end);
    if (n == 3) advance<3>(chains, done, end);
    if (n == 2) advance<2>(chains, done, end);
    if (n == 1) advance<1>(chains, done, end);
    done = std::max(done, end);
  }
}

}  // namespace

region_scorer histogram_scorer(const cv::Mat& bin_indices, const color_histogram& target) {
  return [&bin_indices, normalized_target = target.normalized()](const cv::Rect& box) {
    auto candidate = color_histogram::of_bin_indices(bin_indices, box, normalized_target.bins());
    return intersection(normalized_target, candidate.normalized());
  };
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
// each side), from row `first_row` and column `first_col` of work_ on; the rest is kept:
// I(y + 1, x + 1) = I(y, x + 1) + sum_{x' <= x} P(y, x'), accumulated in double. The zero
// rows above and below B are not stored: row() clamps to rows 0 and height, whose sums they
// equal. The side columns add only zeros, so they are filled by copying instead of summing.
// Entries are computed the same way from scratch and after a removal, so the incremental
// update of step 6 gives bit-identical sums to a full recomputation: a box zeroed in work_
// changes the running sums P only in its own rows, from its left column on, and I only
// below its top row and right of its left column. With `previous` (the integral image before
// the removal) the result goes to a new image and the unchanged entries are copied from it;
// without, `integral` is updated in place.
void multiscale_localizer::update_integral(cv::Mat& integral, const cv::Mat* previous,
                                           int first_row, int first_col, int last_row) {
  const int width = work_.cols;
  const int height = work_.rows;
  const int cols = width + 2 * pad_x_ + 1;
  integral.create(height + 1, cols, CV_64F);
  if (previous == nullptr && first_row == 0 && first_col == 0) {
    std::fill_n(integral.ptr<double>(0), cols, 0.0);
    prefix_.create(height, width, CV_64F);
  } else if (previous != nullptr) {
    // What the removal leaves: the rows down to first_row, and left of first_col below.
    std::copy_n(previous->ptr<double>(0), static_cast<std::size_t>(first_row + 1) * cols,
                integral.ptr<double>(0));
    for (int y = first_row + 1; y <= height; ++y)
      std::copy_n(previous->ptr<double>(y), pad_x_ + 1 + first_col, integral.ptr<double>(y));
  }
  // Pass 1: each row's running sums, eight rows at a time so that their add chains overlap.
  int y = first_row;
  for (; y + 8 <= last_row; y += 8) {
    const float* in[8];
    double* out[8];
    double row_sum[8];
    for (int r = 0; r < 8; ++r) {
      in[r] = work_.ptr<float>(y + r);
      out[r] = prefix_.ptr<double>(y + r);
      row_sum[r] = first_col > 0 ? out[r][first_col - 1] : 0.0;
    }
    for (int x = first_col; x < width; ++x)
      for (int r = 0; r < 8; ++r) out[r][x] = row_sum[r] += in[r][x];
  }
  for (; y < last_row; ++y) {
    const float* in = work_.ptr<float>(y);
    double* out = prefix_.ptr<double>(y);
    double row_sum = first_col > 0 ? out[first_col - 1] : 0.0;
    for (int x = first_col; x < width; ++x) out[x] = row_sum += in[x];
  }
  // Pass 2: I(y + 1, x + 1) = I(y, x + 1) + running sum, for every row from first_row on.
  for (y = first_row; y < height; ++y) {
    const double* sums = prefix_.ptr<double>(y);
    const double* above = integral.ptr<double>(y) + pad_x_ + 1;
    double* out = integral.ptr<double>(y + 1);
    if (first_col == 0) std::fill_n(out, pad_x_ + 1, 0.0);
    out += pad_x_ + 1;
    add_rows(above + first_col, sums + first_col, out + first_col, width - first_col);
    std::fill_n(out + width, pad_x_, out[width - 1]);
  }
}

// Row y of the integral image after `version` removals, at column 0 of B.
const double* multiscale_localizer::row(std::size_t version, int y) const {
  const cv::Mat& integral = integrals_[exact_ ? 0 : version];
  return integral.ptr<double>(std::clamp(y, 0, integral.rows - 1)) + pad_x_;
}

// Fig. 9, steps 1 and 2 for the pixels in `area`: sum_l B_l(x, y), each B_l(x, y) a box sum
// over the integral image after `version` removals (four look-ups), rounded to float and
// added in scale order. The B_l themselves are not stored: steps 3 and 4 need them only near
// the peak. sum_row() runs this with the widest vectors the CPU has, with the same
// operations, hence the same results.
void multiscale_localizer::compute_sum(std::size_t version, const cv::Rect& area) {
  std::array<box_rows, 64> small;
  std::vector<box_rows> large;
  box_rows* rows = small.data();
  const int count = static_cast<int>(scales_.size());
  if (scales_.size() > small.size()) {
    large.resize(scales_.size());
    rows = large.data();
  }
  for (int y = area.y; y < area.y + area.height; ++y) {
    for (int k = 0; k < count; ++k) {
      const int l = scales_[k];
      rows[k] = corners(row(version, y - 3 * l) + area.x, row(version, y + 3 * l + 1) + area.x, l);
    }
    sum_row(rows, count, area.width, sum_.ptr<float>(y) + area.x);
  }
}

// The sum over one tile as the procedure of Fig. 9 would hold it now: every point from the
// integral image of the last removal whose kernels reached it (step 6 recomputes the sum
// there and nowhere else), and -1 inside the accepted boxes.
void multiscale_localizer::compute_tile(std::size_t tile,
                                        const std::vector<localized_region>& found) {
  const cv::Rect image(0, 0, sum_.cols, sum_.rows);
  const int tx = static_cast<int>(tile) % tiles_x_;
  const int ty = static_cast<int>(tile) / tiles_x_;
  const cv::Rect area =
      cv::Rect(tx * tile_width, ty * tile_height, tile_width, tile_height) & image;
  compute_sum(0, area);
  for (std::size_t m = 0; m < removals_ && !exact_; ++m) {
    const cv::Rect again = area & affected_[m];
    if (!again.empty()) compute_sum(m + 1, again);
  }
  for (const auto& region : found) {
    const cv::Rect inside = area & region.box();
    if (!inside.empty()) sum_(inside).setTo(suppressed);
  }
  float best = -std::numeric_limits<float>::infinity();
  for (int y = area.y; y < area.y + area.height; ++y)
    best = std::max(best, max_of(sum_.ptr<float>(y) + area.x, area.width));
  tile_max_[tile] = best;
  tile_done_[tile] = 1;
}

// An upper bound of sum_l B_l over each tile with B >= 0: B_l at any point of the tile is
// at most the sum of B over the tile widened by the kernel, l columns and 3l rows each side.
// Computed from the latest integral image, whose B is the smallest (removals only zero B)
// but gives the same box sums wherever no removal reached. The margin covers rounding: each
// integral entry sums at most width + height rounded terms no larger than the total of B
// (M, largest before any removal), a box sum adds three more, the float conversions and
// additions over n scales stay within n + 2 float roundings of the sum; both the bound and
// the sums carry these errors (unit roundoff 2^-53, taken twice to spare).
void multiscale_localizer::bound_tiles() {
  const int width = sum_.cols;
  const int height = sum_.rows;
  const double n = static_cast<double>(scales_.size()) + 2.0;
  const double total = std::max(0.0, row(0, height)[width]);
  const double margin_abs = 2.0 * n * (4.0 * (width + height) + 16.0) * 0x1p-52 * total;
  const double margin_rel = n * 0x1p-22;
  for (int ty = 0; ty < tiles_y_; ++ty)
    for (int tx = 0; tx < tiles_x_; ++tx) {
      const int x0 = tx * tile_width;
      const int y0 = ty * tile_height;
      const int x1 = std::min(x0 + tile_width, width);
      const int y1 = std::min(y0 + tile_height, height);
      double bound = 0.0;
      for (const int l : scales_) {
        const double* top = row(removals_, y0 - 3 * l);
        const double* bottom = row(removals_, y1 + 3 * l);
        bound += (bottom[x1 + l] - bottom[x0 - l]) - (top[x1 + l] - top[x0 - l]);
      }
      tile_bound_[ty * tiles_x_ + tx] = bound + std::abs(bound) * margin_rel + margin_abs;
    }
}

// Step 2: the first maximum of the sum in row-major order (as cv::minMaxLoc finds it).
// Tiles are computed in decreasing order of their bounds until a bound is below the largest
// value found: no point left out can then reach it, let alone equal it.
cv::Point multiscale_localizer::find_peak(const std::vector<localized_region>& found, float& best) {
  const std::size_t tiles = tile_done_.size();
  best = -std::numeric_limits<float>::infinity();
  for (std::size_t t = 0; t < tiles; ++t)
    if (tile_done_[t] != 0) best = std::max(best, tile_max_[t]);
  if (bounded_) {
    bound_tiles();
    std::sort(tile_order_.begin(), tile_order_.end(),
              [this](int a, int b) { return tile_bound_[a] > tile_bound_[b]; });
  }
  for (const int t : tile_order_) {
    if (bounded_ && (tile_bound_[t] < best || tile_bound_[t] <= empty_response)) break;
    if (tile_done_[t] != 0) continue;
    compute_tile(static_cast<std::size_t>(t), found);
    best = std::max(best, tile_max_[t]);
  }
  // The first point equal to the maximum, in the computed tiles (every other one is lower).
  for (int ty = 0; ty < tiles_y_; ++ty) {
    bool band = false;
    for (int tx = 0; tx < tiles_x_; ++tx) {
      const std::size_t t = static_cast<std::size_t>(ty * tiles_x_ + tx);
      band = band || (tile_done_[t] != 0 && tile_max_[t] == best);
    }
    if (!band) continue;
    for (int y = ty * tile_height; y < std::min((ty + 1) * tile_height, sum_.rows); ++y)
      for (int tx = 0; tx < tiles_x_; ++tx) {
        const std::size_t t = static_cast<std::size_t>(ty * tiles_x_ + tx);
        if (tile_done_[t] == 0 || tile_max_[t] != best) continue;
        const float* values = sum_.ptr<float>(y);
        const int end = std::min((tx + 1) * tile_width, sum_.cols);
        for (int x = tx * tile_width; x < end; ++x)
          if (values[x] == best) return {x, y};
      }
  }
  return {0, 0};  // no tile computed: best is -inf
}

// B_l over `area` into `out` (area.width x area.height, row-major), as compute_sum()
// evaluates it.
void multiscale_localizer::compute_response(int l, const cv::Rect& area, float* out) const {
  for (int y = area.y; y < area.y + area.height; ++y, out += area.width) {
    const box_rows rows =
        corners(row(removals_, y - 3 * l) + area.x, row(removals_, y + 3 * l + 1) + area.x, l);
    sum_row(&rows, 1, area.width, out);
  }
}

const std::vector<cv::Mat>& multiscale_localizer::responses() const {
  if (responses_.size() != scales_.size()) {
    responses_.resize(scales_.size());
    for (std::size_t k = 0; k < scales_.size(); ++k) {
      responses_[k].create(work_.rows, work_.cols, CV_32F);
      compute_response(scales_[k], cv::Rect(0, 0, work_.cols, work_.rows),
                       responses_[k].ptr<float>(0));
    }
  }
  return responses_;
}

std::vector<localized_region> multiscale_localizer::localize(const cv::Mat& backprojection,
                                                             const region_scorer& score) {
  CV_Assert(backprojection.type() == CV_32F);
  std::vector<localized_region> found;
  responses_.clear();
  removals_ = 0;
  affected_.clear();
  const int width = backprojection.cols;
  const int height = backprojection.rows;
  backprojection.copyTo(work_);
  if (width == 0 || height == 0) {
    integrals_.resize(1);
    integrals_[0].release();
    return found;
  }
  scales_ = settings_.scales.empty() ? paper_scales(height) : settings_.scales;
  const int largest = *std::max_element(scales_.begin(), scales_.end());
  CV_Assert(*std::min_element(scales_.begin(), scales_.end()) >= 0);
  pad_x_ = largest + 1;
  const cv::Rect image(0, 0, width, height);
  if (integrals_.empty()) integrals_.resize(1);
  update_integral(integrals_[0], nullptr, 0, 0, height);
  sum_.create(height, width, CV_32F);

  // Step 1 runs tile by tile, where step 2 needs it. The bounds hold for B >= 0 (a
  // backprojection); with negative values (or NaN) every tile is computed.
  //
  // When every value of B is a multiple of some q = 2^e and the sum of B stays below 2^53 q
  // (true of most backprojections: ratios well above 2^-13 at 320x240), every sum in the
  // integral image and every box sum is exact, so the integral images before and after a
  // removal give the same bits wherever no kernel reaches the removed box; then one integral
  // image is kept and updated in place.
  const value_range range = range_of(work_);
  bounded_ = range.nonnegative;
  exact_ = bounded_ && (std::isinf(range.smallest_positive) ||
                        double(width) * height * range.largest <=
                            std::ldexp(1.0, 53 + std::ilogb(range.smallest_positive) - 23));
  tiles_x_ = (width + tile_width - 1) / tile_width;
  tiles_y_ = (height + tile_height - 1) / tile_height;
  const std::size_t tiles = static_cast<std::size_t>(tiles_x_) * tiles_y_;
  tile_bound_.assign(tiles, 0.0);
  tile_max_.assign(tiles, 0.0f);
  tile_done_.assign(tiles, 0);
  tile_order_.resize(tiles);
  for (std::size_t t = 0; t < tiles; ++t) tile_order_[t] = static_cast<int>(t);

  const std::size_t scale_count = scales_.size();
  std::vector<cv::Rect> domains(scale_count);
  std::vector<std::size_t> offsets(scale_count + 1);
  std::vector<double> peaks(scale_count), squares(scale_count);
  std::vector<std::size_t> order(scale_count);
  while (static_cast<int>(found.size()) < settings_.max_regions) {
    // Step 2: the peak of the summed response.
    float best = 0.0f;
    const cv::Point centre = find_peak(found, best);
    if (best <= empty_response) break;

    int best_scale = scales_.front();
    double box_score = 0.0;
    if (settings_.choice == scale_choice::sharpness) {
      // Step 3: per scale, B_l over the kernel domain and its peak.
      offsets[0] = 0;
      for (std::size_t k = 0; k < scale_count; ++k) {
        domains[k] = kernel_domain(centre, scales_[k]) & image;
        offsets[k + 1] = offsets[k] + static_cast<std::size_t>(domains[k].area());
      }
      domain_responses_.resize(offsets[scale_count]);
      for (std::size_t k = 0; k < scale_count; ++k) {
        float* response = domain_responses_.data() + offsets[k];
        compute_response(scales_[k], domains[k], response);
        peaks[k] = max_of(response, domains[k].area());
      }
      // Step 4: sum_K (peak - B_l)^2 per scale, each over its domain in row-major order. The
      // scales' sums are independent chains of dependent adds: they advance four at a time,
      // longest first, so that the adds overlap, each still in its own order.
      for (std::size_t k = 0; k < scale_count; ++k) order[k] = k;
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return offsets[a + 1] - offsets[a] > offsets[b + 1] - offsets[b];
      });
      for (std::size_t group = 0; group < scale_count; group += 4) {
        const std::size_t n = std::min<std::size_t>(4, scale_count - group);
        chain chains[4];
        for (std::size_t c = 0; c < n; ++c) {
          const std::size_t k = order[group + c];
          chains[c] = {domain_responses_.data() + offsets[k], offsets[k + 1] - offsets[k], peaks[k],
                       0.0};
        }
        advance_chains(chains, n);
        for (std::size_t c = 0; c < n; ++c) squares[order[group + c]] = chains[c].squares;
      }
      double best_sharpness = -1.0;
      for (std::size_t k = 0; k < scale_count; ++k) {
        const double sharpness = squares[k] / domains[k].area();
        if (sharpness > best_sharpness) {
          best_sharpness = sharpness;
          best_scale = scales_[k];
        }
      }

      box_score = score(kernel_domain(centre, best_scale) & image);
    } else {
      // The largest size whose box scores within 3 % of the best: floor pixels at a box's
      // margin cost it a little score, and a tracker whose next sizes follow this box would
      // otherwise shrink it frame after frame.
      scores_.clear();
      double best_score = -1.0;
      for (const int l : scales_) {
        scores_.push_back(score(kernel_domain(centre, l) & image));
        best_score = std::max(best_score, scores_.back());
      }
      int chosen = -1;  // sizes may come in any order
      // With an expected size, the one nearest to it among those (larger on a tie): choosing
      // the largest ratchets a tracker's box up a size whenever two score alike.
      const double expected = settings_.expected_scale;
      auto distance = [&](int l) { return std::abs(std::log(l / expected)); };
      auto preferred = [&](int a, int b) {
        if (expected > 0.0 && distance(a) != distance(b)) return distance(a) < distance(b);
        return a > b;
      };
      for (std::size_t k = 0; k < scale_count; ++k) {
        if (scores_[k] < near_best_score * best_score) continue;
        if (chosen < 0 || preferred(scales_[k], chosen)) {
          chosen = scales_[k];
          box_score = scores_[k];
        }
      }
      best_scale = chosen;
    }

    // Step 5: accept the box of size l* centred at (x*, y*) by its score.
    const auto box = kernel_domain(centre, best_scale) & image;
    if (!(box_score > settings_.rho)) break;
    found.push_back({box.x, box.y, box.width, box.height, box_score, best_scale});

    // Step 6: remove the box from B; the sum changes where a kernel reaches it. Only integral
    // entries below the box's top and right of its left side change. The tiles there are
    // computed again when step 2 needs them.
    work_(box).setTo(0.0f);
    ++removals_;
    if (exact_) {
      update_integral(integrals_[0], nullptr, box.y, box.x, box.y + box.height);
    } else {
      if (integrals_.size() <= removals_) integrals_.emplace_back();
      update_integral(integrals_[removals_], &integrals_[removals_ - 1], box.y, box.x,
                      box.y + box.height);
    }
    const cv::Rect affected = cv::Rect(box.x - largest, box.y - 3 * largest,
                                       box.width + 2 * largest, box.height + 6 * largest) &
                              image;
    affected_.push_back(affected);
    for (int ty = affected.y / tile_height; ty <= (affected.br().y - 1) / tile_height; ++ty)
      for (int tx = affected.x / tile_width; tx <= (affected.br().x - 1) / tile_width; ++tx)
        tile_done_[static_cast<std::size_t>(ty * tiles_x_ + tx)] = 0;
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
