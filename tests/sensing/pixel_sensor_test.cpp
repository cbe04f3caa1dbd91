// A node's pixel sensing with the signature in halves (sensing.halves_rho): the operator's pick
// sends her halves in its signature only when they are tested, the signature survives the trip
// into another camera's tracker, and that tracker refuses a look-alike in swapped clothes that
// the paper's sensing takes for her.

#include "sensing/pixel_sensor.hpp"

#include <gtest/gtest.h>

#include "opencv2/imgproc.hpp"
#include "sensing/signature.hpp"

namespace argus::sensing {
namespace {

const cv::Scalar wall(120, 120, 120), blue(140, 60, 20), red(30, 30, 200);

cv::Rect draw_figure(cv::Mat& image, int x, const cv::Scalar& shirt, const cv::Scalar& trousers) {
  cv::rectangle(image, cv::Rect(x, 88, 20, 26), shirt, cv::FILLED);
  cv::rectangle(image, cv::Rect(x, 114, 20, 26), trousers, cv::FILLED);
  return {x, 80, 20, 60};
}

vision::tracker_settings with_halves(double rho) {
  config::sensing_settings sensing;
  sensing.halves_rho = rho;
  return pixel_sensor::settings_for(sensing);
}

struct swapped_clothes : ::testing::Test {
  cv::Mat with_her = cv::Mat(240, 320, CV_8UC3, wall);
  cv::Rect her = draw_figure(with_her, 100, red, blue);
  cv::Mat with_him = [] {
    cv::Mat image(240, 320, CV_8UC3, wall);
    draw_figure(image, 180, blue, red);
    return image;
  }();
};

TEST_F(swapped_clothes, the_paper_sends_one_histogram_and_takes_him_for_her) {
  pixel_sensor picker(with_halves(0.0));
  const auto signature = picker.acquire(1, with_her, {}, her);
  EXPECT_TRUE(signature.upper.empty());
  EXPECT_TRUE(signature.lower.empty());
  pixel_sensor other(with_halves(0.0));
  const auto seen = other.look(with_him, {}, {{1, signature}});
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_TRUE(seen[0].found);
}

TEST_F(swapped_clothes, in_halves_her_signature_carries_them_and_he_is_refused) {
  pixel_sensor picker(with_halves(0.5));
  const auto signature = picker.acquire(1, with_her, {}, her);
  ASSERT_EQ(signature.upper.size(), signature.values.size());
  ASSERT_EQ(signature.lower.size(), signature.values.size());
  const auto halves = to_halves(signature);
  ASSERT_TRUE(halves);
  EXPECT_NEAR(halves->upper.total(), 1.0, 1e-5);
  EXPECT_LT(vision::halves_match(*halves, {halves->lower, halves->upper}), 0.2)
      << "her upper half is red, her lower blue";

  pixel_sensor other(with_halves(0.5));
  EXPECT_FALSE(other.look(with_him, {}, {{1, signature}})[0].found);
  const auto seen = other.look(with_her, {}, {{1, signature}});
  EXPECT_TRUE(seen[0].found);
  EXPECT_GT((cv::Rect(seen[0].box) & her).area(), her.area() / 2);
}

// With signature_update, a tracker that has held her for a few frames and seen her box grow by
// half re-takes its model; the look of that frame carries it (controller.share_model's source).
TEST(pixel_sensor, a_look_carries_the_model_its_tracker_re_took) {
  config::sensing_settings sensing;
  sensing.signature_update = true;
  pixel_sensor picker(pixel_sensor::settings_for(sensing));
  const auto draw = [](int height) {
    cv::Mat image(240, 320, CV_8UC3, wall);
    const int x = 150, top = 60;
    cv::rectangle(image, cv::Rect(x, top, height / 3, height / 2), red, cv::FILLED);
    cv::rectangle(image, cv::Rect(x, top + height / 2, height / 3, height / 2), blue, cv::FILLED);
    return image;
  };
  const auto signature = picker.acquire(1, draw(60), {}, {150, 60, 20, 60});
  std::vector<int> models;
  for (int frame = 0; frame < 20; ++frame) {
    const auto seen = picker.look(draw(frame < 8 ? 60 : 96), {}, {{1, signature}});
    ASSERT_TRUE(seen[0].found) << frame;
    if (seen[0].model) models.push_back(frame);
  }
  ASSERT_FALSE(models.empty());
  EXPECT_GE(models.front(), 8) << "not before her box grew";
  EXPECT_EQ(models.size(), 1u) << "once: her box does not grow again";
}

}  // namespace
}  // namespace argus::sensing
