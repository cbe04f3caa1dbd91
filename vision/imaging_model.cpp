#include "vision/imaging_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

#include "config/derive_seed.hpp"
#include "vision/jpeg_codec.hpp"

namespace argus::vision {
namespace {

// Tag mixed into the run seed so imaging noise streams differ from any other actor stream
// derived from the same camera id.
constexpr std::uint64_t imaging_seed_tag = 0x696d6167696e67ULL;  // "imaging"

void require_bgr(const cv::Mat& frame, const char* what) {
  if (frame.type() != CV_8UC3) {
    throw std::invalid_argument(std::string(what) + ": expected a CV_8UC3 BGR image");
  }
}

// Acklam's rational approximation of the standard normal quantile (relative error < 1.2e-9).
double inverse_normal_cdf(double p) {
  static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                                 -2.759285104469687e+02, 1.383577518672690e+02,
                                 -3.066479806614716e+01, 2.506628277459239e+00};
  static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                                 -1.556989798598866e+02, 6.680131188771972e+01,
                                 -1.328068155288572e+01};
  static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                                 -2.400758277161838e+00, -2.549732539343734e+00,
                                 4.374664141464968e+00,  2.938163982698783e+00};
  static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01,
                                 2.445134137142996e+00, 3.754408661907416e+00};
  constexpr double low = 0.02425;
  if (p < low) {
    const double q = std::sqrt(-2.0 * std::log(p));
    return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  if (p > 1.0 - low) return -inverse_normal_cdf(1.0 - p);
  const double q = p - 0.5;
  const double r = q * q;
  return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
         (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
}

}  // namespace

imaging_model::imaging_model(const config::imaging_model& settings, std::uint64_t seed)
    : settings_(settings), rng_(seed == 0 ? 1 : seed) {}  // cv::RNG treats 0 as "default"

imaging_model imaging_model::for_camera(const config::imaging_model& settings,
                                        std::uint64_t run_seed, int camera_id) {
  return imaging_model(settings,
                       config::derive_seed(config::derive_seed(run_seed, imaging_seed_tag),
                                           static_cast<std::uint64_t>(camera_id)));
}

cv::Mat imaging_model::apply(const cv::Mat& frame) {
  return apply(frame, frame);
}

cv::Mat imaging_model::apply(const cv::Mat& first_field, const cv::Mat& second_field) {
  require_bgr(first_field, "imaging_model");
  return degrade(settings_.interlace ? weave_fields(first_field, second_field)
                                     : first_field.clone());
}

cv::Mat imaging_model::degrade(cv::Mat frame) {
  require_bgr(frame, "imaging_model");
  cv::Mat out = std::move(frame);
  if (settings_.color_response_enabled) apply_color_response(out, settings_.response);
  if (settings_.noise_sigma > 0.0) add_detector_noise(out, settings_.noise_sigma, rng_);
  if (settings_.dropout_fraction > 0.0) {
    add_dropout(out, settings_.dropout_fraction, settings_.dropout, rng_);
  }
  last_jpeg_.clear();
  if (settings_.jpeg_quality > 0) {
    out = jpeg_round_trip(out, static_cast<int>(settings_.jpeg_quality), last_jpeg_);
  }
  return out;
}

cv::Mat weave_fields(const cv::Mat& first_field, const cv::Mat& second_field) {
  require_bgr(first_field, "weave_fields");
  if (second_field.size() != first_field.size() || second_field.type() != first_field.type()) {
    throw std::invalid_argument("weave_fields: the two fields differ in size or type");
  }
  cv::Mat out = first_field.clone();
  for (int row = 1; row < out.rows; row += 2) second_field.row(row).copyTo(out.row(row));
  return out;
}

void apply_color_response_to_every_pixel(cv::Mat& frame, const config::color_response& r) {
  require_bgr(frame, "apply_color_response_to_every_pixel");
  const bool hsv_identity = r.hue_offset_deg == 0.0 && r.saturation_gain == 1.0 &&
                            r.value_gain == 1.0 && r.value_offset == 0.0;
  if (!hsv_identity) {
    // 8-bit HSV with the full hue range (0-255 for 0-360 degrees) and one lookup table per
    // channel: three passes over the image instead of per-pixel float work, at the price of
    // hue steps of 1.4 degrees.
    cv::Mat table(1, 256, CV_8UC3);
    const double hue_steps = r.hue_offset_deg * 256.0 / 360.0;
    for (int i = 0; i < 256; ++i) {
      const long hue = std::lround(i + hue_steps);
      table.at<cv::Vec3b>(0, i) =
          cv::Vec3b(static_cast<uchar>(((hue % 256) + 256) % 256),
                    cv::saturate_cast<uchar>(i * r.saturation_gain),
                    cv::saturate_cast<uchar>(i * r.value_gain + 255.0 * r.value_offset));
    }
    cv::cvtColor(frame, frame, cv::COLOR_BGR2HSV_FULL);
    cv::LUT(frame, table, frame);
    cv::cvtColor(frame, frame, cv::COLOR_HSV2BGR_FULL);
  }
  // Tints, tones and shades: mixing in white, grey and black ([42] in the paper).
  double scale = 1.0;
  double offset = 0.0;
  auto mix = [&](double amount, double toward) {
    scale *= 1.0 - amount;
    offset = offset * (1.0 - amount) + amount * toward;
  };
  mix(r.tint, 255.0);
  mix(r.tone, 127.5);
  mix(r.shade, 0.0);
  if (scale != 1.0 || offset != 0.0) frame.convertTo(frame, CV_8UC3, scale, offset);
}

namespace {

// The distinct colours of a frame (open addressing on the packed colour, in a table small
// enough to stay in the first-level cache); gives up past `most` colours.
class palette {
 public:
  static constexpr std::uint16_t empty = 0xffff;
  static constexpr std::size_t most = 2048;

  explicit palette(const cv::Mat& frame) {
    slots_.fill(empty);
    const auto* p = frame.ptr<cv::Vec3b>();
    const std::size_t n = frame.total();
    std::uint32_t last = pack(p[0]) + 1;  // not p[0]'s
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t key = pack(p[i]);
      if (key == last) continue;
      last = key;
      std::size_t h = slot_of(key);
      if (slots_[h] == empty) {
        if (colours_.size() == most) {
          complete_ = false;
          return;
        }
        slots_[h] = static_cast<std::uint16_t>(colours_.size());
        colours_.push_back(key);
      }
    }
  }
  bool complete() const noexcept { return complete_; }
  std::size_t size() const noexcept { return colours_.size(); }
  std::uint32_t colour(std::size_t k) const { return colours_[k]; }
  /// The index of a colour of the frame.
  std::size_t index_of(const cv::Vec3b& pixel) const { return slots_[slot_of(pack(pixel))]; }
  static std::uint32_t pack(const cv::Vec3b& p) {
    return p[0] | (static_cast<std::uint32_t>(p[1]) << 8) |
           (static_cast<std::uint32_t>(p[2]) << 16);
  }

 private:
  static constexpr std::size_t slots = 2 * most;
  // The slot holding `key`, or the empty one where it would go.
  std::size_t slot_of(std::uint32_t key) const {
    std::size_t h = ((key * 0x9e3779b1u) >> 16) & (slots - 1);
    while (slots_[h] != empty && colours_[slots_[h]] != key) h = (h + 1) & (slots - 1);
    return h;
  }
  std::array<std::uint16_t, slots> slots_;
  std::vector<std::uint32_t> colours_;
  bool complete_ = true;
};

}  // namespace

void apply_color_response(cv::Mat& frame, const config::color_response& r) {
  require_bgr(frame, "apply_color_response");
  if (!frame.isContinuous()) frame = frame.clone();
  // The response is a function of each pixel's colour alone, and a rendered frame (flat faces,
  // a two-tone floor) has a few hundred colours in 76,800 pixels: each colour is transformed
  // once, in rows as wide as the frame's (so that OpenCV takes the same code path for every
  // pixel as on the frame itself: the same bytes), and painted back. A frame of many colours
  // (noise before the response, a photograph) is transformed whole.
  const palette colours(frame);
  if (!colours.complete()) {
    apply_color_response_to_every_pixel(frame, r);
    return;
  }
  const int width = frame.cols;
  const auto count = static_cast<int>(colours.size());
  cv::Mat swatches((count + width - 1) / width, width, CV_8UC3, cv::Scalar(0, 0, 0));
  auto* s = swatches.ptr<cv::Vec3b>();
  for (int k = 0; k < count; ++k) {
    const auto c = colours.colour(static_cast<std::size_t>(k));
    s[k] =
        cv::Vec3b(static_cast<uchar>(c), static_cast<uchar>(c >> 8), static_cast<uchar>(c >> 16));
  }
  apply_color_response_to_every_pixel(swatches, r);
  s = swatches.ptr<cv::Vec3b>();
  auto* p = frame.ptr<cv::Vec3b>();
  const std::size_t n = frame.total();
  // Neighbours mostly share a colour: the last one's answer is kept.
  cv::Vec3b last_in = p[0];
  cv::Vec3b last_out = s[colours.index_of(p[0])];
  for (std::size_t i = 0; i < n; ++i) {
    if (p[i] != last_in) {
      last_in = p[i];
      last_out = s[colours.index_of(p[i])];
    }
    p[i] = last_out;
  }
}

void add_detector_noise(cv::Mat& frame, double sigma, cv::RNG& rng) {
  require_bgr(frame, "add_detector_noise");
  if (sigma <= 0.0) return;
  // Inverse-CDF sampling from a table of 65,536 equiprobable quantiles of N(0, sigma^2):
  // one 16-bit uniform per sample, two per RNG call, instead of a Gaussian draw per sample
  // (6x faster; the tails are cut at 4.3 sigma, which 8-bit pixels never miss).
  static thread_local double table_sigma = -1.0;
  static thread_local std::vector<std::int16_t> table(65536);
  if (table_sigma != sigma) {
    for (int i = 0; i < 65536; ++i) {
      const double q = inverse_normal_cdf((i + 0.5) / 65536.0) * sigma;
      table[static_cast<std::size_t>(i)] =
          static_cast<std::int16_t>(std::clamp(std::lround(q), -255L, 255L));
    }
    table_sigma = sigma;
  }
  if (!frame.isContinuous()) frame = frame.clone();
  uchar* data = frame.ptr<uchar>();
  const std::size_t n = frame.total() * 3;
  std::size_t i = 0;
  auto add = [&](std::uint32_t bits) {
    data[i] = cv::saturate_cast<uchar>(data[i] + table[bits]);
    ++i;
  };
  for (; i + 1 < n;) {
    const std::uint32_t bits = rng.next();
    add(bits & 0xffffu);
    add(bits >> 16);
  }
  if (i < n) add(rng.next() & 0xffffu);
}

std::size_t add_dropout(cv::Mat& frame, double fraction, config::dropout_kind kind, cv::RNG& rng) {
  require_bgr(frame, "add_dropout");
  if (fraction <= 0.0) return 0;
  if (!frame.isContinuous()) frame = frame.clone();
  const std::size_t pixels = frame.total();
  auto* data = frame.ptr<cv::Vec3b>();
  std::size_t count = 0;
  bool salt = true;
  auto corrupt = [&](cv::Vec3b& p) {
    switch (kind) {
      case config::dropout_kind::snow:
        p = cv::Vec3b(255, 255, 255);
        break;
      case config::dropout_kind::bit_flip:
        p = cv::Vec3b(static_cast<uchar>(~p[0]), static_cast<uchar>(~p[1]),
                      static_cast<uchar>(~p[2]));
        break;
      case config::dropout_kind::salt_and_pepper:
        p = salt ? cv::Vec3b(255, 255, 255) : cv::Vec3b(0, 0, 0);
        salt = !salt;
        break;
    }
    ++count;
  };
  if (fraction >= 1.0) {
    for (std::size_t i = 0; i < pixels; ++i) corrupt(data[i]);
    return count;
  }
  // Geometric gaps between corrupted pixels: the same law as one Bernoulli draw per pixel,
  // with one random number per corrupted pixel instead of one per pixel.
  const double log_keep = std::log1p(-fraction);
  std::size_t i = 0;
  while (true) {
    const double u = 1.0 - rng.uniform(0.0, 1.0);  // (0, 1]
    const double gap = std::floor(std::log(u) / log_keep);
    if (gap >= static_cast<double>(pixels - i)) break;
    i += static_cast<std::size_t>(gap);
    corrupt(data[i]);
    if (++i >= pixels) break;
  }
  return count;
}

cv::Mat jpeg_round_trip(const cv::Mat& frame, int quality, std::size_t* encoded_bytes) {
  std::vector<std::uint8_t> bytes;
  auto out = jpeg_round_trip(frame, quality, bytes);
  if (encoded_bytes != nullptr) *encoded_bytes = bytes.size();
  return out;
}

cv::Mat jpeg_round_trip(const cv::Mat& frame, int quality, std::vector<std::uint8_t>& encoded) {
  require_bgr(frame, "jpeg_round_trip");
  encode_jpeg(frame, quality, encoded);
  return decode_jpeg(encoded);
}

}  // namespace argus::vision
