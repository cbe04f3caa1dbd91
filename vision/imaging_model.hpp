#pragma once

#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "config/scenario.hpp"

namespace argus::vision {

/// The imaging model of Section III-A: turns a clean rendered frame into what a cheap
/// surveillance camera delivers. Effects, each off or on per `config::imaging_model`, applied
/// in the order a real camera would:
///
///   fields --weave--> colour response --> detector noise --> data dropout --> JPEG round trip
///   (sensor)          (HSV, tint/tone/shade) (Gaussian)       (transmission)   (bandwidth)
///
/// One instance per camera, with its own RNG (cv::RNG, seeded from the run seed and the
/// camera id through config::derive_seed), so that a camera's noise is the same in every run
/// with the same seed, whichever thread applies it. Not thread-safe: one thread at a time.
class imaging_model {
 public:
  /// The model of `settings`, its noise drawn from `seed`.
  imaging_model(const config::imaging_model& settings, std::uint64_t seed);

  /// The model of camera `camera_id` in a run seeded with `run_seed`.
  static imaging_model for_camera(const config::imaging_model& settings, std::uint64_t run_seed,
                                  int camera_id);

  /// Degrades a progressive frame (CV_8UC3, BGR); with interlacing on, the same frame stands
  /// in for both fields.
  cv::Mat apply(const cv::Mat& frame);

  /// Degrades an interlaced frame: even rows from `first_field` (rendered at t), odd rows
  /// from `second_field` (rendered half a frame later, t + tick / 2). With interlacing off,
  /// only `first_field` is used.
  cv::Mat apply(const cv::Mat& first_field, const cv::Mat& second_field);

  /// Degrades a frame whose fields are woven already (renderer::render_interlaced), or a
  /// progressive one: colour response, noise, dropout and JPEG, without the weave.
  cv::Mat degrade(cv::Mat frame);

  /// Whether the renderer should provide two fields per frame.
  bool interlaced() const noexcept { return settings_.interlace; }

  /// The settings.
  const config::imaging_model& settings() const noexcept { return settings_; }

  /// Size of the last JPEG encoding in bytes (0 when JPEG is off): the bandwidth a frame
  /// would cost on the network.
  std::size_t last_jpeg_bytes() const noexcept { return last_jpeg_.size(); }
  /// The JPEG encoding of the last degraded frame (empty when JPEG is off). JPEG is the last
  /// step, so decoding it gives that frame's pixels: a frame can travel as these bytes.
  const std::vector<std::uint8_t>& last_jpeg() const noexcept { return last_jpeg_; }
  /// Where the noise stands: with the same settings, a model given this state draws the same
  /// noise from here on. A camera's frames can so be degraded in another process, in turn,
  /// with only this number crossing (actors/video_tiles.hpp).
  std::uint64_t noise_state() const noexcept { return rng_.state; }
  void set_noise_state(std::uint64_t state) noexcept { rng_.state = state; }

 private:
  config::imaging_model settings_;
  cv::RNG rng_;
  std::vector<std::uint8_t> last_jpeg_;
};

/// Even rows of `first_field`, odd rows of `second_field` (same size and type).
cv::Mat weave_fields(const cv::Mat& first_field, const cv::Mat& second_field);

/// Colour response in 8-bit HSV (hue in steps of 360/256 degrees): hue + hue_offset_deg
/// (wrapping), saturation * saturation_gain,
/// value * value_gain + value_offset (value and value_offset as fractions of full scale,
/// 1 = 255), clipped to range; then c = (1 - tint) c + tint white, c = (1 - tone) c + tone
/// grey (50 %), c = (1 - shade) c (mixing with black), in that order.
void apply_color_response(cv::Mat& frame, const config::color_response& response);

/// The same response computed for every pixel of the frame, in OpenCV's passes over it:
/// what apply_color_response does to a frame of many colours, and the reference it is tested
/// against (it transforms each distinct colour of a rendered frame once).
void apply_color_response_to_every_pixel(cv::Mat& frame, const config::color_response& response);

/// Adds zero-mean Gaussian noise of `sigma` (8-bit units) to every channel, saturating.
void add_detector_noise(cv::Mat& frame, double sigma, cv::RNG& rng);

/// Corrupts each pixel independently with probability `fraction`: snow sets it to 255, a bit
/// flip inverts every bit, salt and pepper alternates 255 and 0. Returns the count corrupted.
std::size_t add_dropout(cv::Mat& frame, double fraction, config::dropout_kind kind, cv::RNG& rng);

/// JPEG encode at `quality` (1-100) and decode; `encoded_bytes`, if given, receives the size
/// of the encoding.
cv::Mat jpeg_round_trip(const cv::Mat& frame, int quality, std::size_t* encoded_bytes = nullptr);
/// The same, keeping the encoding in `encoded`.
cv::Mat jpeg_round_trip(const cv::Mat& frame, int quality, std::vector<std::uint8_t>& encoded);

}  // namespace argus::vision
