// The emulated sensor's visibility and error model on hand-placed pedestrians in Penn
// Station, next to the concourse/waiting-room wall at x = 65:
//
//        camera (57, 35, 4 m) --> looking east
//          |   A (62, 35)   | wall x = 65 |   B (70, 35), behind the wall
#include "vision/emulated_sensor.hpp"

#include <gtest/gtest.h>

#include "world/layout_loader.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::vision {
namespace {

const world::station& penn() {
  static const auto shared = world::station::load(world::builtin_layout_path());
  return *shared;
}

camera_view view_east() {
  camera_view view;
  view.placement.position_m = {57.0, 35.0, 4.0};
  view.pose = {0.0, -25.0, 60.0};
  view.width_px = 320;
  view.height_px = 240;
  return view;
}

world::pedestrian_state person(int id, double x, double y, world::rgb8 shirt = {200, 30, 30}) {
  world::pedestrian_state p;
  p.id = id;
  p.position = {x, y};
  p.look.shirt = shirt;
  p.look.trousers = {20, 20, 120};
  p.look.skin = {200, 160, 130};
  p.look.hair = {40, 30, 20};
  return p;
}

world::snapshot frame_of(std::vector<world::pedestrian_state> people) {
  return world::snapshot(penn(), 0, std::chrono::duration<double>(0.0), std::move(people));
}

// A model that never misses above the hard limits and never confuses, with exact boxes.
sensor_model perfect() {
  sensor_model model;
  model.miss_bias = -50.0;
  model.confusion_bias = -50.0;
  model.box_sigma = 0.0;
  return model;
}

double iou(const cv::Rect& a, const cv::Rect& b) {
  const double shared = (a & b).area();
  return shared / (a.area() + b.area() - shared);
}

TEST(emulated_sensor, an_unoccluded_pedestrian_in_view_is_detected_with_its_true_box) {
  const auto view = view_east();
  const auto frame = frame_of({person(1, 62.0, 35.0)});
  const auto seen = visible_pedestrians(frame, penn(), view);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_DOUBLE_EQ(seen[0].occlusion, 0.0);
  // The box spans the projections of the feet and the head.
  const auto foot = *view.project({62.0, 35.0, 0.0});
  const auto head = *view.project({62.0, 35.0, 1.7});
  EXPECT_NEAR(seen[0].box.y, head.y(), 1e-6);
  EXPECT_NEAR(seen[0].box.y + seen[0].box.height, foot.y(), 1e-6);
  EXPECT_GT(seen[0].box.height, 40.0);

  emulated_sensor sensor(perfect(), 7);
  const auto found = sensor.detect(frame, penn(), view);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].pedestrian_id, 1);
  const cv::Rect truth(seen[0].box);
  EXPECT_GT(iou(found[0].box, truth), 0.9);
  EXPECT_NEAR(found[0].confidence, perfect().confidence_unoccluded, 1e-9);
  EXPECT_GT(normalized_intersection(found[0].signature, appearance_signature(frame.find(1)->look)),
            0.999);
  const auto looked = sensor.look_for(1, frame, penn(), view);
  EXPECT_TRUE(looked.found);
  EXPECT_FALSE(looked.confused);
}

TEST(emulated_sensor, a_pedestrian_behind_a_wall_is_not_seen) {
  const auto view = view_east();
  ASSERT_FALSE(penn().line_clear({64.7, 35.0}, {65.3, 35.0}));
  const auto frame = frame_of({person(2, 70.0, 35.0)});
  // Without the wall it would be in the image.
  EXPECT_TRUE(view.project({70.0, 35.0, 1.0}).has_value());
  EXPECT_TRUE(visible_pedestrians(frame, penn(), view).empty());
  emulated_sensor sensor(perfect(), 7);
  EXPECT_TRUE(sensor.detect(frame, penn(), view).empty());
  EXPECT_FALSE(sensor.look_for(2, frame, penn(), view).found);
}

TEST(emulated_sensor, a_fully_occluded_pedestrian_is_missed) {
  const auto view = view_east();
  auto front = person(1, 62.5, 35.0);
  front.look.height_m = 2.3;  // a tall, broad occluder right in front of the other
  front.look.girth_m = 1.2;
  const auto frame = frame_of({front, person(2, 63.5, 35.0, {30, 200, 30})});
  const auto seen = visible_pedestrians(frame, penn(), view);
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0].id, 1);
  EXPECT_GT(seen[1].occlusion, perfect().max_occlusion);
  emulated_sensor sensor(perfect(), 7);
  for (int k = 0; k < 20; ++k) {
    const auto found = sensor.detect(frame, penn(), view);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].pedestrian_id, 1);
    EXPECT_FALSE(sensor.look_for(2, frame, penn(), view).found);
  }
}

TEST(emulated_sensor, misses_grow_with_occlusion_and_small_size_and_confusions_with_similarity) {
  emulated_sensor sensor(sensor_model{}, 1);
  EXPECT_LT(sensor.miss_probability(0.0, 100.0), sensor.miss_probability(0.5, 100.0));
  EXPECT_LT(sensor.miss_probability(0.0, 100.0), sensor.miss_probability(0.0, 15.0));
  EXPECT_EQ(sensor.miss_probability(0.95, 100.0), 1.0);
  EXPECT_LT(sensor.confusion_probability(0.2), sensor.confusion_probability(0.9));
}

TEST(emulated_sensor, identical_twins_are_confused_at_the_models_rate) {
  const auto view = view_east();
  // Two pedestrians side by side, same clothes: similarity 1.
  const auto frame = frame_of({person(1, 63.0, 34.4), person(2, 63.0, 35.6)});
  sensor_model model = perfect();
  model.confusion_bias = -1.0;
  model.confusion_per_similarity = 1.0;  // P(confusion) = 1/2 at similarity 1
  emulated_sensor sensor(model, 11);
  int confused = 0;
  const int trials = 2000;
  for (int k = 0; k < trials; ++k) {
    const auto looked = sensor.look_for(1, frame, penn(), view);
    ASSERT_TRUE(looked.found);
    if (looked.confused) {
      ++confused;
      EXPECT_EQ(looked.detection.pedestrian_id, 2);
    }
  }
  EXPECT_NEAR(static_cast<double>(confused) / trials, 0.5, 0.05);
}

TEST(emulated_sensor, the_same_seed_gives_the_same_errors) {
  const auto view = view_east();
  const auto frame = frame_of({person(1, 63.0, 34.4), person(2, 63.0, 35.6)});
  auto a = emulated_sensor::for_camera(sensor_model{}, 42, 3);
  auto b = emulated_sensor::for_camera(sensor_model{}, 42, 3);
  for (int k = 0; k < 50; ++k) {
    const auto x = a.detect(frame, penn(), view);
    const auto y = b.detect(frame, penn(), view);
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(x[i].box, y[i].box);
  }
}

TEST(sensor_model, yaml_round_trip_and_errors) {
  sensor_model model;
  model.miss_bias = -3.25;
  model.confusion_per_similarity = 7.5;
  model.samples = 1234;
  EXPECT_EQ(sensor_model_from_yaml(to_yaml(model)), model);
  EXPECT_EQ(sensor_model_from_yaml("miss_bias: 2\n").miss_bias, 2.0);
  EXPECT_THROW(sensor_model_from_yaml("miss_bais: 2\n"), std::runtime_error);
  EXPECT_THROW(sensor_model_from_yaml("miss_bias: lots\n"), std::runtime_error);
}

}  // namespace
}  // namespace argus::vision
