#include "vision/imaging_model.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace argus::vision {
namespace {

cv::Mat grey(int value = 128) {
  return cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(value));
}

// A frame with sharp colour edges: red and blue halves and a green square.
cv::Mat edges() {
  cv::Mat f(240, 320, CV_8UC3, cv::Scalar(0, 0, 220));
  f(cv::Rect(160, 0, 160, 240)).setTo(cv::Scalar(200, 40, 0));
  f(cv::Rect(60, 60, 80, 80)).setTo(cv::Scalar(30, 200, 30));
  return f;
}

TEST(imaging_model, detector_noise_has_the_configured_sigma) {
  config::imaging_model settings;
  settings.noise_sigma = 8.0;
  auto model = imaging_model::for_camera(settings, 7, 3);
  const cv::Mat clean = grey();
  const cv::Mat noisy = model.apply(clean);
  cv::Mat diff;
  cv::Mat(noisy).convertTo(diff, CV_64FC3);
  diff -= cv::Scalar::all(128.0);
  cv::Scalar mean, sigma;
  cv::meanStdDev(diff.reshape(1), mean, sigma);
  EXPECT_NEAR(mean[0], 0.0, 0.1);
  // Rounding to integers adds 1/12 to the variance.
  EXPECT_NEAR(sigma[0], std::sqrt(64.0 + 1.0 / 12.0), 0.1);
}

TEST(imaging_model, dropout_corrupts_the_configured_fraction) {
  for (auto kind : {config::dropout_kind::snow, config::dropout_kind::bit_flip,
                    config::dropout_kind::salt_and_pepper}) {
    config::imaging_model settings;
    settings.dropout_fraction = 0.05;
    settings.dropout = kind;
    imaging_model model(settings, 11);
    const cv::Mat out = model.apply(grey(100));
    int white = 0;
    int black = 0;
    int flipped = 0;
    for (auto it = out.begin<cv::Vec3b>(); it != out.end<cv::Vec3b>(); ++it) {
      if (*it == cv::Vec3b(255, 255, 255)) ++white;
      if (*it == cv::Vec3b(0, 0, 0)) ++black;
      if (*it == cv::Vec3b(155, 155, 155)) ++flipped;  // ~100
    }
    const double n = static_cast<double>(out.total());
    // 76,800 pixels: the binomial standard deviation of the fraction is 0.0008.
    switch (kind) {
      case config::dropout_kind::snow:
        EXPECT_NEAR(white / n, 0.05, 0.004);
        break;
      case config::dropout_kind::bit_flip:
        EXPECT_NEAR(flipped / n, 0.05, 0.004);
        break;
      case config::dropout_kind::salt_and_pepper:
        EXPECT_NEAR((white + black) / n, 0.05, 0.004);
        EXPECT_NEAR(white, black, 1);
        break;
    }
  }
}

TEST(imaging_model, jpeg_is_smaller_and_differs_near_colour_edges) {
  config::imaging_model settings;
  settings.jpeg_quality = 30;
  imaging_model model(settings, 1);
  const cv::Mat clean = edges();
  const cv::Mat out = model.apply(clean);
  EXPECT_GT(model.last_jpeg_bytes(), 0u);
  EXPECT_LT(model.last_jpeg_bytes(), clean.total() * clean.elemSize() / 10);
  cv::Mat diff;
  cv::absdiff(out, clean, diff);
  diff = diff.reshape(1);
  // Near the red/blue edge (column 160) artefacts are strong; far inside a flat area weak.
  double edge_max = 0.0;
  double flat_max = 0.0;
  cv::minMaxLoc(diff(cv::Rect(3 * 156, 160, 3 * 8, 40)), nullptr, &edge_max);
  cv::minMaxLoc(diff(cv::Rect(3 * 224, 160, 3 * 48, 40)), nullptr, &flat_max);
  EXPECT_GT(edge_max, 20.0);
  EXPECT_LT(flat_max, 8.0);
}

TEST(imaging_model, color_response_shifts_hue_as_configured) {
  config::imaging_model settings;
  settings.color_response_enabled = true;
  settings.response.hue_offset_deg = 120.0;  // red -> green
  imaging_model model(settings, 1);
  const cv::Mat red(8, 8, CV_8UC3, cv::Scalar(0, 0, 200));
  const cv::Vec3b shifted = model.apply(red).at<cv::Vec3b>(4, 4);
  // Hue comes in steps of 1.4 degrees: a little red may remain.
  EXPECT_LE(shifted[0], 2);
  EXPECT_NEAR(shifted[1], 200, 1);
  EXPECT_LE(shifted[2], 6);
  // Saturation gain 0.5 halves the chroma; value gain scales the maximum channel.
  config::color_response r;
  r.saturation_gain = 0.5;
  r.value_gain = 0.5;
  cv::Mat f = red.clone();
  apply_color_response(f, r);
  EXPECT_LE(cv::norm(f.at<cv::Vec3b>(0, 0), cv::Vec3b(50, 50, 100), cv::NORM_INF), 1.0);
  // Tint mixes with white, shade with black, tone with grey.
  config::color_response tint;
  tint.tint = 0.5;
  f = grey(0);
  apply_color_response(f, tint);
  EXPECT_NEAR(f.at<cv::Vec3b>(0, 0)[0], 128, 1);
  config::color_response shade;
  shade.shade = 0.25;
  f = grey(200);
  apply_color_response(f, shade);
  EXPECT_EQ(f.at<cv::Vec3b>(0, 0)[1], 150);
  config::color_response tone;
  tone.tone = 1.0;
  f = edges();
  apply_color_response(f, tone);
  EXPECT_NEAR(f.at<cv::Vec3b>(0, 0)[2], 128, 1);
}

TEST(imaging_model, effects_are_off_unless_configured) {
  imaging_model model(config::imaging_model{}, 5);
  const cv::Mat clean = edges();
  EXPECT_EQ(cv::norm(model.apply(clean), clean, cv::NORM_INF), 0.0);
}

TEST(imaging_model, interlacing_weaves_even_and_odd_rows) {
  config::imaging_model settings;
  settings.interlace = true;
  imaging_model model(settings, 1);
  const cv::Mat woven = model.apply(grey(10), grey(200));
  EXPECT_EQ(woven.at<cv::Vec3b>(0, 5)[0], 10);
  EXPECT_EQ(woven.at<cv::Vec3b>(1, 5)[0], 200);
  EXPECT_EQ(woven.at<cv::Vec3b>(238, 5)[0], 10);
  EXPECT_EQ(woven.at<cv::Vec3b>(239, 5)[0], 200);
}

TEST(imaging_model, noise_is_deterministic_per_camera) {
  config::imaging_model settings;
  settings.noise_sigma = 5.0;
  settings.dropout_fraction = 0.01;
  auto a = imaging_model::for_camera(settings, 42, 1);
  auto b = imaging_model::for_camera(settings, 42, 1);
  auto c = imaging_model::for_camera(settings, 42, 2);
  const cv::Mat clean = grey();
  const cv::Mat fa = a.apply(clean);
  EXPECT_EQ(cv::norm(fa, b.apply(clean), cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(fa, c.apply(clean), cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace argus::vision
