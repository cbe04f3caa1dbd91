#include "vision/signature_update.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "opencv2/imgproc.hpp"
#include "vision/tracker.hpp"

namespace argus::vision {
namespace {

const cv::Scalar grey(120, 120, 120), red(30, 30, 200), blue(140, 60, 20), green(40, 170, 40);

TEST(signature_update, the_core_is_the_middle_of_the_box) {
  const signature_update_settings s;  // half the width, 80 % of the height
  EXPECT_EQ(body_core({10, 20, 40, 100}, s), cv::Rect(20, 30, 20, 80));
  EXPECT_EQ(body_core({0, 0, 1, 1}, s).area(), 1);
}

TEST(signature_update, a_model_is_due_once_confirmed_and_her_size_has_changed) {
  const signature_update_settings s;  // 5 frames, a factor 1.4
  EXPECT_FALSE(model_due(4, 100, 50, s));
  EXPECT_TRUE(model_due(5, 100, 50, s));
  EXPECT_FALSE(model_due(5, 60, 50, s));
  EXPECT_TRUE(model_due(5, 30, 50, s));
  EXPECT_TRUE(model_due(5, 30, 0, s)) << "a signature as received is replaced once confirmed";
}

TEST(signature_update, the_model_blends_the_signature_with_her_core) {
  cv::Mat image(100, 60, CV_8UC3, grey);
  cv::rectangle(image, cv::Rect(15, 10, 30, 80), green, cv::FILLED);
  const cv::Mat indices = bin_index_image(image);
  color_histogram signature(histogram_bins{});
  signature.counts()[bin_index_image(cv::Mat(1, 1, CV_8UC3, red)).at<std::uint16_t>(0, 0)] = 1.0f;
  const auto model = blended_model(signature, indices, {15, 10, 30, 80}, {});
  const auto green_bin = bin_index_image(cv::Mat(1, 1, CV_8UC3, green)).at<std::uint16_t>(0, 0);
  const auto red_bin = bin_index_image(cv::Mat(1, 1, CV_8UC3, red)).at<std::uint16_t>(0, 0);
  EXPECT_NEAR(model[green_bin], 0.5, 1e-6);  // the core holds only her
  EXPECT_NEAR(model[red_bin], 0.5, 1e-6);
  EXPECT_NEAR(model.total(), 1.0, 1e-6);
}

// A figure seen first from afar, as a red top over blue legs, 30 px tall; the camera zooms in
// (her box grows 8 % a frame) and shows what the distance hid: a green jacket over most of
// her, up to 70 % of her height. The signature from afar knows no green: her score against it
// falls to about 0.3, below rho = 0.4, and the paper's tracker loses her. Re-taking the model
// from the camera's own view on the way keeps her.
//
//   frame 0: 30 px, no green    frame 19: 130 px, 70 % green
//   +--+                        +------+
//   |rr|                        |rrrrrr|
//   |bb|                        |gggggg|  ...
//   +--+                        |bbbbbb|
TEST(signature_update, a_tracker_that_retakes_its_model_keeps_her_through_the_zoom) {
  auto frame_at = [&](int k, cv::Rect& truth) {
    cv::Mat image(240, 320, CV_8UC3, grey);
    const int h = static_cast<int>(std::lround(30.0 * std::pow(1.08, k)));
    const int w = h / 3;
    truth = cv::Rect(160 - w / 2, 120 - h / 2, w, h);
    const int jacket = static_cast<int>(std::lround(h * 0.7 * k / 19.0));
    const int top = (h - jacket) / 2;
    cv::rectangle(image, cv::Rect(truth.x, truth.y, w, top), red, cv::FILLED);
    cv::rectangle(image, cv::Rect(truth.x, truth.y + top, w, jacket), green, cv::FILLED);
    cv::rectangle(image, cv::Rect(truth.x, truth.y + top + jacket, w, h - top - jacket), blue,
                  cv::FILLED);
    return image;
  };
  cv::Rect truth;
  const auto first = frame_at(0, truth);
  const auto signature = color_histogram::of_region(first, truth).normalized();
  for (const bool update : {true, false}) {
    tracker_settings settings;
    settings.update_signature = update;
    settings.search_whole_frame = false;
    tracker t(signature, settings);
    t.start(truth);
    int held = 0;
    for (int k = 1; k < 20; ++k) {
      const auto image = frame_at(k, truth);
      const auto seen = t.update(image);
      if (!seen.found) break;
      const auto centre = (seen.box.tl() + seen.box.br()) / 2;
      if (!truth.contains(centre)) break;
      ++held;
    }
    if (update) {
      EXPECT_EQ(held, 19) << "the model re-taken on the way keeps her";
    } else {
      EXPECT_LT(held, 19) << "the signature from afar no longer matches her";
    }
  }
}

// A member's tracker starts from a signature another camera sent, and finds its first box in
// its whole frame, where a look-alike is as likely as she is: that box is not trusted to
// re-take the model until the track has held it while her size changed (here, a zoom).
TEST(signature_update, a_signature_from_a_message_is_kept_until_her_size_changes) {
  auto frame_with = [](int h) {
    cv::Mat image(240, 320, CV_8UC3, grey);
    const int w = h / 3;
    cv::rectangle(image, cv::Rect(160 - w / 2, 120 - h / 2, w, h / 2), red, cv::FILLED);
    cv::rectangle(image, cv::Rect(160 - w / 2, 120, w, h - h / 2), green, cv::FILLED);
    return image;
  };
  // The sender saw her top as red and her legs as blue; this camera sees green legs.
  cv::Mat sent(240, 320, CV_8UC3, grey);
  cv::rectangle(sent, cv::Rect(150, 90, 20, 30), red, cv::FILLED);
  cv::rectangle(sent, cv::Rect(150, 120, 20, 30), blue, cv::FILLED);
  const auto signature = color_histogram::of_region(sent, {150, 90, 20, 60}).normalized();
  tracker_settings settings;
  settings.update_signature = true;
  settings.search_whole_frame = true;
  tracker t(signature, settings);
  for (int k = 0; k < 10; ++k) ASSERT_TRUE(t.update(frame_with(60)).found);
  EXPECT_EQ(t.model(), t.target()) << "held ten frames at one size: not re-taken";
  for (int h = 66; h <= 100; h += 6) ASSERT_TRUE(t.update(frame_with(h)).found);
  EXPECT_NE(t.model(), t.target()) << "her size changed by 1.4 on a held track: re-taken";
}

}  // namespace
}  // namespace argus::vision
