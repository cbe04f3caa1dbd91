// The figure-ground test (surround_match, tracker_settings::max_surround_match): a person
// matches the ring around her little, a patch of wall matches it fully; a tracker with the test
// refuses a box on the wall that the paper's tracker takes for her.

#include "vision/surround_match.hpp"

#include <gtest/gtest.h>

#include <array>

#include "opencv2/imgproc.hpp"
#include "vision/tracker.hpp"

namespace argus::vision {
namespace {

const cv::Scalar wall(120, 120, 120), blue(140, 60, 20), red(30, 30, 200);

// A figure 60 px tall whose top is the wall's grey and whose trousers are blue.
cv::Rect draw_figure(cv::Mat& image, int x) {
  cv::rectangle(image, cv::Rect(x, 80, 20, 30), wall, cv::FILLED);
  cv::rectangle(image, cv::Rect(x, 110, 20, 30), blue, cv::FILLED);
  return {x, 80, 20, 60};
}

double match(const cv::Mat& bgr, const cv::Rect& box) {
  const histogram_bins bins;
  return surround_match(bin_index_image(bgr, bins), box, bins);
}

TEST(surround_match, a_figure_matches_its_surround_little_a_wall_fully) {
  cv::Mat image(240, 320, CV_8UC3, wall);
  cv::rectangle(image, cv::Rect(200, 80, 20, 60), red, cv::FILLED);
  EXPECT_LT(match(image, {200, 80, 20, 60}), 0.05) << "red on grey";
  EXPECT_GT(match(image, {40, 40, 20, 60}), 0.99) << "grey in grey";
  const auto her = draw_figure(image, 100);
  EXPECT_NEAR(match(image, her), 0.5, 0.05) << "her grey top is the wall's, her trousers not";
}

TEST(surround_match, an_empty_box_or_ring_matches_nothing) {
  const cv::Mat image(240, 320, CV_8UC3, wall);
  EXPECT_EQ(match(image, {400, 40, 20, 60}), 0.0) << "outside the image";
  EXPECT_EQ(match(image, {0, 0, 320, 240}), 0.0) << "no ring left inside the image";
}

TEST(surround_match, a_tracker_with_the_test_refuses_the_wall_and_takes_her) {
  cv::Mat with_her(240, 320, CV_8UC3, wall);
  const auto her = draw_figure(with_her, 100);
  const auto signature = color_histogram::of_region(with_her, her).normalized();
  const cv::Mat empty(240, 320, CV_8UC3, wall);
  tracker_settings paper;
  EXPECT_TRUE(tracker(signature, paper).update(empty).found)
      << "the paper's tracker takes half her colours, a grey patch, for her";
  tracker_settings figure_ground;
  figure_ground.max_surround_match = 0.65;
  EXPECT_FALSE(tracker(signature, figure_ground).update(empty).found);
  const auto seen = tracker(signature, figure_ground).update(with_her);
  ASSERT_TRUE(seen.found);
  EXPECT_GT((seen.box & her).area(), her.area() / 2);
}

// The operator picks her against the wall: her grey top makes her match the wall by 0.5, which
// a test at 0.4 refuses.
struct grey_top_pick : ::testing::Test {
  cv::Mat with_her = cv::Mat(240, 320, CV_8UC3, wall);
  cv::Rect her = draw_figure(with_her, 100);
  color_histogram signature = color_histogram::of_region(with_her, her).normalized();
  tracker_settings strict = [] {
    tracker_settings s;
    s.max_surround_match = 0.4;
    return s;
  }();
};

// The pick is spared the test for surround_grace_frames unbroken frames.
TEST_F(grey_top_pick, the_operators_pick_is_spared_the_test_for_its_grace_frames_only) {
  tracker no_grace(signature, strict);
  no_grace.start(her);
  EXPECT_FALSE(no_grace.update(with_her).found) << "without grace her pick is refused at once";

  strict.surround_grace_frames = 3;
  tracker graced(signature, strict);
  graced.start(her);
  for (int frame = 0; frame < 3; ++frame)
    EXPECT_TRUE(graced.update(with_her).found) << "frame " << frame << " of the grace";
  EXPECT_FALSE(graced.update(with_her).found) << "the grace is over";
  EXPECT_FALSE(graced.update(with_her).found) << "a lost track gets no new grace";

  tracker broken(signature, strict);
  broken.start(her);
  EXPECT_TRUE(broken.update(with_her).found);
  const cv::Mat black(240, 320, CV_8UC3, cv::Scalar(0, 0, 0));
  EXPECT_FALSE(broken.update(black).found);
  EXPECT_FALSE(broken.update(with_her).found) << "the chain from her pick was broken";
}

// surround_grace_height_px: the pick is also spared the test while its box is shorter than that,
// however many frames it lasts; a box taller than the limit is tested.
TEST_F(grey_top_pick, the_operators_pick_is_spared_the_test_while_her_box_is_small) {
  strict.surround_grace_height_px = her.height + 30;
  tracker small(signature, strict);
  small.start(her);
  for (int frame = 0; frame < 30; ++frame) {
    const auto seen = small.update(with_her);
    ASSERT_TRUE(seen.found) << "frame " << frame;
    ASSERT_LT(seen.box.height, strict.surround_grace_height_px);
  }
  strict.surround_grace_height_px = her.height / 2;
  tracker tall(signature, strict);
  tall.start(her);
  EXPECT_FALSE(tall.update(with_her).found) << "her box is taller than the limit: tested";
}

// surround_patience_frames: a live track's box that fails the test is still hers until it has
// failed in that many frames running; a frame that passes starts the count again.
TEST_F(grey_top_pick, a_box_is_taken_for_background_only_after_its_patience) {
  tracker at_once(signature, strict);
  at_once.start(her);
  EXPECT_FALSE(at_once.update(with_her).found) << "patience 1: refused at the first failure";

  strict.surround_patience_frames = 3;
  tracker patient(signature, strict);
  patient.start(her);
  EXPECT_TRUE(patient.update(with_her).found) << "first failure";
  EXPECT_TRUE(patient.update(with_her).found) << "second failure";
  EXPECT_FALSE(patient.update(with_her).found) << "the third in a row: background";
  EXPECT_FALSE(patient.update(with_her).found)
      << "a lost track's finds elsewhere are tested at once";

  // On red her grey top stands out: her ring matches her little, and the strikes end.
  cv::Mat on_red(240, 320, CV_8UC3, red);
  draw_figure(on_red, 100);
  ASSERT_LT(surround_match(bin_index_image(on_red, histogram_bins{}), her, histogram_bins{}),
            strict.max_surround_match);
  tracker reset(signature, strict);
  reset.start(her);
  EXPECT_TRUE(reset.update(with_her).found);
  EXPECT_TRUE(reset.update(with_her).found);
  EXPECT_TRUE(reset.update(on_red).found) << "passes the test";
  EXPECT_TRUE(reset.update(with_her).found) << "the count started again";
  EXPECT_TRUE(reset.update(with_her).found);
  EXPECT_FALSE(reset.update(with_her).found);
}

// A queue of three people in red tops and blue trousers, shoulder to shoulder against the wall;
// returns the middle one's box.
cv::Rect draw_queue(cv::Mat& image) {
  for (const int x : {80, 100, 120}) {
    cv::rectangle(image, cv::Rect(x, 80, 20, 30), red, cv::FILLED);
    cv::rectangle(image, cv::Rect(x, 110, 20, 30), blue, cv::FILLED);
  }
  return {100, 80, 20, 60};
}

std::array<double, 4> sides(const cv::Mat& bgr, const cv::Rect& box) {
  const histogram_bins bins;
  return surround_side_matches(bin_index_image(bgr, bins), box, bins);
}

TEST(surround_side_matches, her_neighbours_match_her_at_her_sides_only) {
  cv::Mat image(240, 320, CV_8UC3, wall);
  const auto her = draw_queue(image);
  const auto matched = sides(image, her);
  EXPECT_GT(matched[0], 0.99) << "left: the neighbour dressed like her";
  EXPECT_GT(matched[1], 0.99) << "right";
  EXPECT_LT(matched[2], 0.01) << "above: the wall";
  EXPECT_LT(matched[3], 0.01) << "below";
  EXPECT_NEAR(match(image, her), 0.5, 0.05) << "the whole ring is half her neighbours";
  EXPECT_EQ(sides_matching(matched, 0.4), 2);
  const auto wall_patch = sides(image, {240, 40, 20, 60});
  EXPECT_EQ(sides_matching(wall_patch, 0.99), 4) << "a patch of wall matches all round";
}

TEST(surround_side_matches, a_side_outside_the_image_does_not_count) {
  const cv::Mat image(240, 320, CV_8UC3, wall);
  const auto matched = sides(image, {0, 0, 20, 60});
  EXPECT_EQ(matched[0], -1.0) << "left of the image";
  EXPECT_EQ(matched[2], -1.0) << "above the image";
  EXPECT_GT(matched[1], 0.99);
  EXPECT_GT(matched[3], 0.99);
  EXPECT_EQ(sides_matching(matched, 0.5), 2);
  EXPECT_TRUE(background_by_sides(matched, 0.5, 3)) << "every side inside the image matches";
  EXPECT_FALSE(background_by_sides({-1.0, 0.9, -1.0, 0.1}, 0.5, 3)) << "one of two";
  EXPECT_FALSE(background_by_sides({-1.0, -1.0, -1.0, -1.0}, 0.5, 1)) << "no side to test";
}

// surround_sides: her box in a queue of look-alikes matches the whole ring as much as a patch of
// wall half her colour does; counted by sides, the wall is refused and she is kept.
TEST(surround_side_matches, a_tracker_testing_by_sides_keeps_her_in_a_queue_and_refuses_the_wall) {
  cv::Mat queue(240, 320, CV_8UC3, wall);
  const auto her = draw_queue(queue);
  const auto in_red = color_histogram::of_region(queue, her).normalized();
  tracker_settings ring;
  ring.max_surround_match = 0.4;
  tracker whole(in_red, ring);
  whole.start(her);
  EXPECT_FALSE(whole.update(queue).found) << "the whole ring refuses her among her neighbours";

  tracker_settings by_sides = ring;
  by_sides.surround_sides = 3;
  tracker kept(in_red, by_sides);
  kept.start(her);
  const auto seen = kept.update(queue);
  ASSERT_TRUE(seen.found) << "two sides of four match her: still a figure";
  EXPECT_GT((seen.box & cv::Rect(80, 80, 60, 60)).area(), her.area() / 2);

  cv::Mat with_her(240, 320, CV_8UC3, wall);
  const auto grey_top = draw_figure(with_her, 100);
  const auto signature = color_histogram::of_region(with_her, grey_top).normalized();
  const cv::Mat empty(240, 320, CV_8UC3, wall);
  by_sides.max_surround_match = 0.65;
  EXPECT_FALSE(tracker(signature, by_sides).update(empty).found)
      << "a grey patch matches the wall on every side";
  by_sides.surround_sides = 4;
  EXPECT_FALSE(tracker(signature, by_sides).update(empty).found) << "on all four";
}

}  // namespace
}  // namespace argus::vision
