// A worker's camera frames cross to the coordinator with their fixed parts as one block
// (actors/wire_frames.hpp): every field comes back bit for bit, in the same order under the same
// camera, a frame costs its head's bytes and nothing per field, and counts that do not add up fail.

#include "actors/wire_frames.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

#include "actors/wire_log.hpp"
#include "caf/binary_deserializer.hpp"
#include "caf/binary_serializer.hpp"

namespace argus::actors::testing {
namespace {

using eval::camera_frame;
using frames_by_camera = std::map<int, std::vector<camera_frame>>;

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

frames_by_camera some_frames() {
  frames_by_camera out;
  for (int camera : {3, 7, 1024}) {
    for (std::int64_t tick = 0; tick < 5; ++tick) {
      camera_frame f;
      f.tick = tick * 3 + camera;
      f.camera = camera;
      f.pose = {-0.0, -20.0 - camera, 60.0 / (tick + 1)};
      f.state = static_cast<eval::frame_state>(tick % 3);
      if (camera == 7 && tick >= 2)
        for (std::uint32_t task = 0; task < static_cast<std::uint32_t>(tick); ++task) {
          eval::look_record look;
          look.task = task;
          look.leader = task == 0;
          look.found = tick % 2 == 0;
          look.box = {1.5 * task, 2.25, 10.0 + tick, std::numeric_limits<double>::quiet_NaN()};
          look.score = 0.1 * tick;
          look.truth = static_cast<int>(task) - 1;
          look.iou = 0.3;
          look.observed = task == 1;
          f.looks.push_back(look);
        }
      if (camera == 1024 && tick % 2 == 1)
        for (int p = 0; p < 3; ++p) f.visible.push_back({p * 11, {p * 1.0, 2.0, 3.0, 4.0}, 0.5});
      out[camera].push_back(f);
    }
  }
  return out;
}

void expect_same(const frames_by_camera& a, const frames_by_camera& b) {
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [camera, frames] : a) {
    ASSERT_TRUE(b.contains(camera)) << camera;
    const auto& other = b.at(camera);
    ASSERT_EQ(frames.size(), other.size()) << camera;
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const auto &x = frames[i], &y = other[i];
      EXPECT_EQ(x.tick, y.tick);
      EXPECT_EQ(x.camera, y.camera);
      EXPECT_EQ(bits(x.pose.pan_deg), bits(y.pose.pan_deg));
      EXPECT_EQ(bits(x.pose.tilt_deg), bits(y.pose.tilt_deg));
      EXPECT_EQ(bits(x.pose.field_of_view_deg), bits(y.pose.field_of_view_deg));
      EXPECT_EQ(x.state, y.state);
      ASSERT_EQ(x.looks.size(), y.looks.size());
      for (std::size_t k = 0; k < x.looks.size(); ++k) {
        const auto &l = x.looks[k], &m = y.looks[k];
        EXPECT_EQ(l.task, m.task);
        EXPECT_EQ(l.leader, m.leader);
        EXPECT_EQ(l.found, m.found);
        EXPECT_EQ(bits(l.box.x), bits(m.box.x));
        EXPECT_EQ(bits(l.box.height), bits(m.box.height));
        EXPECT_EQ(bits(l.score), bits(m.score));
        EXPECT_EQ(l.truth, m.truth);
        EXPECT_EQ(l.observed, m.observed);
      }
      ASSERT_EQ(x.visible.size(), y.visible.size());
      for (std::size_t k = 0; k < x.visible.size(); ++k) {
        EXPECT_EQ(x.visible[k].pedestrian, y.visible[k].pedestrian);
        EXPECT_EQ(bits(x.visible[k].box.x), bits(y.visible[k].box.x));
        EXPECT_EQ(bits(x.visible[k].visibility), bits(y.visible[k].visibility));
      }
    }
  }
}

std::vector<char> bytes_of(frames_by_camera frames) {
  std::vector<char> bytes;
  caf::binary_serializer sink{nullptr, bytes};
  auto wire = as_frames(frames);
  EXPECT_FALSE(sink(wire));
  return bytes;
}

TEST(wire_frames, a_workers_frames_come_back_bit_for_bit_under_their_cameras) {
  eval::observation_log::contents sent;
  sent.frames = some_frames();
  sent.origins.push_back({4, 17, 7, 30, eval::target_choice::pixel});
  std::vector<char> bytes;
  caf::binary_serializer sink{nullptr, bytes};
  ASSERT_FALSE(sink(sent));
  eval::observation_log::contents back;
  caf::binary_deserializer source{nullptr, bytes};
  ASSERT_FALSE(source(back));
  EXPECT_EQ(source.remaining(), 0u);
  expect_same(sent.frames, back.frames);
  ASSERT_EQ(back.origins.size(), 1u);
  EXPECT_EQ(back.origins[0].pedestrian, 17);
}

TEST(wire_frames, a_frame_costs_its_head_and_nothing_per_field) {
  auto frames = some_frames();
  const auto before = bytes_of(frames).size();
  for (std::int64_t tick = 100; tick < 300; ++tick)
    frames[3].push_back({tick, 3, {1.0, 2.0, 3.0}, eval::frame_state::idle, {}, {}});
  // 200 more frames: their heads, and the block's count one byte longer (it grows past 127).
  EXPECT_EQ(bytes_of(frames).size(), before + 200 * sizeof(frame_head) + 1);
}

TEST(wire_frames, counts_that_do_not_add_up_are_refused) {
  auto frames = some_frames();
  std::vector<frame_head> heads;
  std::vector<eval::look_record> looks;
  std::vector<eval::visible_box> visible;
  for (const auto& [key, list] : frames)
    for (const auto& f : list) {
      heads.push_back(detail::head_of(key, f));
      looks.insert(looks.end(), f.looks.begin(), f.looks.end());
      visible.insert(visible.end(), f.visible.begin(), f.visible.end());
    }
  frames_by_camera back;
  auto fewer_looks = looks;
  fewer_looks.pop_back();
  EXPECT_TRUE(detail::frames_of(heads, fewer_looks, visible, back));
  auto more_boxes = visible;
  more_boxes.push_back({});
  auto all_looks = looks;
  EXPECT_TRUE(detail::frames_of(heads, all_looks, more_boxes, back));
  auto bad_state = heads;
  bad_state.front().state = 3;
  all_looks = looks;
  auto all_boxes = visible;
  EXPECT_TRUE(detail::frames_of(bad_state, all_looks, all_boxes, back));
  all_looks = looks;
  all_boxes = visible;
  EXPECT_FALSE(detail::frames_of(heads, all_looks, all_boxes, back));
  expect_same(frames, back);
}

}  // namespace
}  // namespace argus::actors::testing
