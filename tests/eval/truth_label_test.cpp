#include "eval/truth_label.hpp"

#include <gtest/gtest.h>

namespace argus::eval {
namespace {

vision::pedestrian_view seen(int id, cv::Rect2d box, double occlusion = 0.0) {
  vision::pedestrian_view v;
  v.id = id;
  v.box = box;
  v.occlusion = occlusion;
  return v;
}

TEST(truth_label, a_tight_box_on_the_target_observes_her) {
  const std::vector<vision::pedestrian_view> visible{seen(3, {100, 50, 20, 60}),
                                                     seen(7, {160, 50, 20, 60})};
  const auto l = label_box({98, 48, 24, 64}, 3, visible, 320, 240);
  EXPECT_EQ(l.truth, 3);
  EXPECT_TRUE(l.observed);
  EXPECT_NEAR(l.iou, (20.0 * 60.0) / (24.0 * 64.0), 1e-9);
}

TEST(truth_label, a_box_that_covers_someone_else_more_is_a_swap) {
  const std::vector<vision::pedestrian_view> visible{seen(3, {100, 50, 20, 60}),
                                                     seen(7, {115, 50, 20, 60})};
  // Holds the target's centre (110, 80) but covers pedestrian 7 more.
  const auto l = label_box({108, 50, 30, 60}, 3, visible, 320, 240);
  EXPECT_EQ(l.truth, 7);
  EXPECT_FALSE(l.observed);
  EXPECT_GT(l.iou, 0.0);
}

TEST(truth_label, a_box_that_misses_her_centre_does_not_observe_her) {
  const std::vector<vision::pedestrian_view> visible{seen(3, {100, 50, 20, 60})};
  const auto l = label_box({100, 50, 20, 20}, 3, visible, 320, 240);
  EXPECT_EQ(l.truth, 3);
  EXPECT_FALSE(l.observed);
}

TEST(truth_label, hidden_or_absent_pedestrians_are_nobody) {
  const std::vector<vision::pedestrian_view> visible{seen(3, {100, 50, 20, 60}, 0.95),
                                                     seen(4, {400, 50, 20, 60})};
  const auto l = label_box({100, 50, 20, 60}, 3, visible, 320, 240);
  EXPECT_EQ(l.truth, -1);
  EXPECT_FALSE(l.observed);
  EXPECT_EQ(l.iou, 0.0);
}

}  // namespace
}  // namespace argus::eval
