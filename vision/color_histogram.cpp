#include "vision/color_histogram.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

#include "opencv2/imgproc.hpp"

namespace argus::vision {
namespace {

constexpr std::uint8_t format_version = 1;
constexpr std::size_t header_bytes = 2 + 1 + 3 + 2;
constexpr std::size_t entry_bytes = 2 + 4;

bool valid(const histogram_bins& bins) {
  return bins.hue >= 1 && bins.hue <= 255 && bins.saturation >= 1 && bins.saturation <= 255 &&
         bins.value >= 1 && bins.value <= 255 && bins.count() <= 65535;
}

void put_u16(std::vector<std::uint8_t>& out, std::uint16_t v) {
  out.push_back(static_cast<std::uint8_t>(v & 0xff));
  out.push_back(static_cast<std::uint8_t>(v >> 8));
}

std::uint16_t get_u16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}

}  // namespace

namespace {

// map(c) as three look-up tables on OpenCV's 8-bit H, S and V whose sum is the bin index.
struct bin_tables {
  std::array<std::uint16_t, 256> hue{}, saturation{}, value{};

  explicit bin_tables(const histogram_bins& bins) {
    for (int i = 0; i < 256; ++i) {
      int h = std::min(i, 179) * bins.hue / 180;
      int s = i * bins.saturation / 256;
      int v = i * bins.value / 256;
      hue[i] = static_cast<std::uint16_t>(h * bins.saturation * bins.value);
      saturation[i] = static_cast<std::uint16_t>(s * bins.value);
      value[i] = static_cast<std::uint16_t>(v);
    }
  }
};

// The HSV image of `bgr` in a buffer kept per thread (no allocation per frame).
const cv::Mat& hsv_of(const cv::Mat& bgr) {
  thread_local cv::Mat hsv;
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
  return hsv;
}

}  // namespace

cv::Mat bin_index_image(const cv::Mat& bgr, const histogram_bins& bins) {
  CV_Assert(bgr.type() == CV_8UC3 && valid(bins));
  const cv::Mat& hsv = hsv_of(bgr);
  const bin_tables map(bins);
  cv::Mat indices(bgr.size(), CV_16U);
  for (int y = 0; y < hsv.rows; ++y) {
    const auto* in = hsv.ptr<std::uint8_t>(y);
    auto* out = indices.ptr<std::uint16_t>(y);
    for (int x = 0; x < hsv.cols; ++x, in += 3)
      out[x] = map.hue[in[0]] + map.saturation[in[1]] + map.value[in[2]];
  }
  return indices;
}

color_histogram bin_index_image(const cv::Mat& bgr, const histogram_bins& bins, cv::Mat& indices) {
  CV_Assert(bgr.type() == CV_8UC3 && valid(bins));
  const cv::Mat& hsv = hsv_of(bgr);
  const bin_tables map(bins);
  indices.create(bgr.size(), CV_16U);
  // Eight integer sub-histograms, so that runs of one colour do not wait on one counter;
  // integer counts below 2^24 convert to float exactly, as of_bin_indices() counts.
  const std::size_t n = static_cast<std::size_t>(bins.count());
  thread_local std::vector<std::uint32_t> parts;
  parts.assign(8 * n, 0);
  for (int y = 0; y < hsv.rows; ++y) {
    const auto* in = hsv.ptr<std::uint8_t>(y);
    auto* out = indices.ptr<std::uint16_t>(y);
    int x = 0;
    for (; x + 8 <= hsv.cols; x += 8, in += 24)
      for (int k = 0; k < 8; ++k) {
        const std::uint16_t i =
            map.hue[in[3 * k]] + map.saturation[in[3 * k + 1]] + map.value[in[3 * k + 2]];
        out[x + k] = i;
        ++parts[k * n + i];
      }
    for (; x < hsv.cols; ++x, in += 3) {
      const std::uint16_t i = map.hue[in[0]] + map.saturation[in[1]] + map.value[in[2]];
      out[x] = i;
      ++parts[i];
    }
  }
  color_histogram result(bins);
  auto counts = result.counts();
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t sum = 0;
    for (std::size_t k = 0; k < 8; ++k) sum += parts[k * n + i];
    counts[i] = static_cast<float>(sum);
  }
  return result;
}

color_histogram::color_histogram() : color_histogram(histogram_bins{}) {
  // nop
}

color_histogram::color_histogram(const histogram_bins& bins)
    : bins_(bins), counts_(static_cast<std::size_t>(bins.count()), 0.0f) {
  CV_Assert(valid(bins));
}

color_histogram color_histogram::of_image(const cv::Mat& bgr, const histogram_bins& bins,
                                          const cv::Mat& mask) {
  auto indices = bin_index_image(bgr, bins);
  if (mask.empty()) return of_bin_indices(indices, cv::Rect(0, 0, bgr.cols, bgr.rows), bins);
  CV_Assert(mask.type() == CV_8U && mask.size() == bgr.size());
  color_histogram result(bins);
  for (int y = 0; y < indices.rows; ++y) {
    const auto* in = indices.ptr<std::uint16_t>(y);
    const auto* m = mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < indices.cols; ++x)
      if (m[x] != 0) result.counts_[in[x]] += 1.0f;
  }
  return result;
}

color_histogram color_histogram::of_region(const cv::Mat& bgr, const cv::Rect& region,
                                           const histogram_bins& bins) {
  auto clipped = region & cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (clipped.empty()) return color_histogram(bins);
  return of_image(bgr(clipped), bins);
}

color_histogram color_histogram::of_bin_indices(const cv::Mat& bin_indices, const cv::Rect& region,
                                                const histogram_bins& bins) {
  CV_Assert(bin_indices.type() == CV_16U);
  color_histogram result(bins);
  auto clipped = region & cv::Rect(0, 0, bin_indices.cols, bin_indices.rows);
  const std::size_t n = static_cast<std::size_t>(bins.count());
  // Four integer sub-histograms, so that runs of one colour do not wait on the same counter;
  // integer counts below 2^24 convert to float exactly, as the float sums were.
  std::vector<std::uint32_t> parts(4 * (n + 1), 0);
  for (int y = clipped.y; y < clipped.y + clipped.height; ++y) {
    const auto* in = bin_indices.ptr<std::uint16_t>(y);
    int x = clipped.x;
    const int end = clipped.x + clipped.width;
    // Out-of-range indices count into bin n of each part, which is dropped.
    auto slot = [n](std::uint16_t i) { return i < n ? std::size_t{i} : n; };
    for (; x + 4 <= end; x += 4) {
      ++parts[slot(in[x])];
      ++parts[(n + 1) + slot(in[x + 1])];
      ++parts[2 * (n + 1) + slot(in[x + 2])];
      ++parts[3 * (n + 1) + slot(in[x + 3])];
    }
    for (; x < end; ++x) ++parts[slot(in[x])];
  }
  for (std::size_t i = 0; i < n; ++i)
    result.counts_[i] = static_cast<float>(parts[i] + parts[(n + 1) + i] + parts[2 * (n + 1) + i] +
                                           parts[3 * (n + 1) + i]);
  return result;
}

double color_histogram::total() const noexcept {
  double sum = 0.0;
  for (float c : counts_) sum += c;
  return sum;
}

color_histogram color_histogram::normalized() const {
  auto result = *this;
  double sum = total();
  if (sum > 0.0)
    for (auto& c : result.counts_) c = static_cast<float>(c / sum);
  return result;
}

std::vector<std::uint8_t> color_histogram::serialize() const {
  std::vector<std::uint8_t> out{'A',
                                'H',
                                format_version,
                                static_cast<std::uint8_t>(bins_.hue),
                                static_cast<std::uint8_t>(bins_.saturation),
                                static_cast<std::uint8_t>(bins_.value)};
  auto non_empty = std::count_if(counts_.begin(), counts_.end(), [](float c) { return c != 0; });
  put_u16(out, static_cast<std::uint16_t>(non_empty));
  for (std::size_t i = 0; i < counts_.size(); ++i) {
    if (counts_[i] == 0.0f) continue;
    put_u16(out, static_cast<std::uint16_t>(i));
    auto bits = std::bit_cast<std::uint32_t>(counts_[i]);
    for (int k = 0; k < 4; ++k) out.push_back(static_cast<std::uint8_t>(bits >> (8 * k)));
  }
  return out;
}

std::optional<color_histogram> color_histogram::deserialize(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < header_bytes || bytes[0] != 'A' || bytes[1] != 'H' ||
      bytes[2] != format_version)
    return std::nullopt;
  histogram_bins bins{bytes[3], bytes[4], bytes[5]};
  if (!valid(bins)) return std::nullopt;
  std::size_t entries = get_u16(bytes.data() + 6);
  if (bytes.size() != header_bytes + entries * entry_bytes) return std::nullopt;
  color_histogram result(bins);
  const auto* p = bytes.data() + header_bytes;
  for (std::size_t e = 0; e < entries; ++e, p += entry_bytes) {
    std::size_t index = get_u16(p);
    std::uint32_t bits = 0;
    for (int k = 0; k < 4; ++k) bits |= static_cast<std::uint32_t>(p[2 + k]) << (8 * k);
    float count = std::bit_cast<float>(bits);
    if (index >= result.counts_.size() || !(count >= 0.0f) || count == 0.0f) return std::nullopt;
    result.counts_[index] = count;
  }
  return result;
}

double intersection(const color_histogram& target, const color_histogram& candidate) {
  if (target.bins() != candidate.bins()) return 0.0;
  double shared = 0.0, sum = 0.0;
  auto t = target.counts();
  auto h = candidate.counts();
  for (std::size_t i = 0; i < t.size(); ++i) {
    shared += std::min(t[i], h[i]);
    sum += t[i];
  }
  return sum > 0.0 ? shared / sum : 0.0;
}

double normalized_intersection(const color_histogram& target, const color_histogram& candidate) {
  return intersection(target.normalized(), candidate.normalized());
}

}  // namespace argus::vision
