#include "vision/multiscale_localizer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

std::vector<int> paper_scales(int frame_height_px) {
  std::vector<int> scales;
  for (int k = 1; k <= 10; ++k) {
    int l = static_cast<int>(std::lround(0.1 * k * frame_height_px / 7.0));
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

// Fig. 9, step 1, for the pixels in `area`: B_l(x, y) is a box sum over the integral image of
// the zero-padded B, four look-ups per pixel and scale; then the sum over l (step 2).
void multiscale_localizer::compute_responses(const cv::Rect& area) {
  for (std::size_t k = 0; k < scales_.size(); ++k) {
    const int l = scales_[k];
    for (int y = area.y; y < area.y + area.height; ++y) {
      const double* top = integral_.ptr<double>(pad_y_ + y - 3 * l) + pad_x_;
      const double* bottom = integral_.ptr<double>(pad_y_ + y + 3 * l + 1) + pad_x_;
      float* out = responses_[k].ptr<float>(y);
      for (int x = area.x; x < area.x + area.width; ++x)
        out[x] =
            static_cast<float>((bottom[x + l + 1] - bottom[x - l]) - (top[x + l + 1] - top[x - l]));
    }
  }
  for (int y = area.y; y < area.y + area.height; ++y) {
    float* sum = sum_.ptr<float>(y);
    std::fill(sum + area.x, sum + area.x + area.width, 0.0f);
    for (const auto& response : responses_) {
      const float* in = response.ptr<float>(y);
      for (int x = area.x; x < area.x + area.width; ++x) sum[x] += in[x];
    }
  }
}

std::vector<localized_region> multiscale_localizer::localize(const cv::Mat& backprojection,
                                                             const region_scorer& score) {
  CV_Assert(backprojection.type() == CV_32F);
  std::vector<localized_region> found;
  const int width = backprojection.cols;
  const int height = backprojection.rows;
  if (width == 0 || height == 0) return found;
  scales_ = settings_.scales.empty() ? paper_scales(height) : settings_.scales;
  const int largest = *std::max_element(scales_.begin(), scales_.end());
  CV_Assert(*std::min_element(scales_.begin(), scales_.end()) >= 0);
  pad_x_ = largest + 1;
  pad_y_ = 3 * largest + 1;
  padded_.create(height + 2 * pad_y_, width + 2 * pad_x_, CV_32F);
  padded_.setTo(0.0f);
  const cv::Rect image(0, 0, width, height);
  cv::Mat inner = padded_(image + cv::Point(pad_x_, pad_y_));
  backprojection.copyTo(inner);
  cv::integral(padded_, integral_, CV_64F);
  responses_.resize(scales_.size());
  for (auto& response : responses_) response.create(height, width, CV_32F);
  sum_.create(height, width, CV_32F);

  // Step 1 (all of the image) and the sum for step 2.
  compute_responses(image);

  while (static_cast<int>(found.size()) < settings_.max_regions) {
    // Step 2: the peak of the summed response.
    double best = 0.0;
    cv::Point centre;
    cv::minMaxLoc(sum_, nullptr, &best, nullptr, &centre);
    if (best <= empty_response) break;

    // Steps 3 and 4: per scale, the peak inside the kernel domain and its sharpness.
    int best_scale = scales_.front();
    double best_sharpness = -1.0;
    for (std::size_t k = 0; k < scales_.size(); ++k) {
      const int l = scales_[k];
      const auto domain = kernel_domain(centre, l) & image;
      const cv::Mat values = responses_[k](domain);
      double peak = 0.0;
      cv::minMaxLoc(values, nullptr, &peak);
      double squares = 0.0;
      for (int y = 0; y < values.rows; ++y) {
        const float* row = values.ptr<float>(y);
        for (int x = 0; x < values.cols; ++x) {
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

    // Step 6: remove the box from B and recompute B_l and the sum where a kernel reaches it.
    inner(box).setTo(0.0f);
    cv::integral(padded_, integral_, CV_64F);
    const cv::Rect affected = cv::Rect(box.x - largest, box.y - 3 * largest,
                                       box.width + 2 * largest, box.height + 6 * largest) &
                              image;
    compute_responses(affected);
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
