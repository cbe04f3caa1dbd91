#pragma once

// A worker's camera frames as they cross to the coordinator (its log at the end of a run, or
// every tick under `--on-worker-loss crash-nodes`): the fixed part of every frame in one block
// of bytes (wire_block.hpp), then their looks and visible boxes. Field by field, the large
// station's 1,024 cameras wrote and read nine fields a frame through CAF's virtual calls, three
// hundred thousand frames for a 20 s run, while the coordinator waited for the workers' logs.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <map>
#include <type_traits>
#include <vector>

#include "actors/wire_block.hpp"
#include "caf/deserializer.hpp"
#include "caf/error.hpp"
#include "caf/sec.hpp"
#include "caf/serializer.hpp"
#include "eval/records.hpp"

namespace argus::actors {

/// What every frame has, as it crosses: the map's key, the frame's own fields, and how many of
/// the looks and visible boxes that follow the block are its.
struct frame_head {
  std::int64_t tick = 0;
  std::uint64_t pan_bits = 0;
  std::uint64_t tilt_bits = 0;
  std::uint64_t field_of_view_bits = 0;
  std::int32_t key = 0;
  std::int32_t camera = 0;
  std::uint32_t state = 0;
  std::uint32_t looks = 0;
  std::uint32_t visible = 0;
  std::uint32_t unused = 0;  // no padding: the block crosses as its bytes
};

/// observation_log::contents::frames (by camera, in tick order), as an inspector names it.
struct frames_wire {
  std::map<int, std::vector<eval::camera_frame>>& frames;
};

inline frames_wire as_frames(std::map<int, std::vector<eval::camera_frame>>& frames) {
  return {frames};
}

namespace detail {

inline frame_head head_of(int key, const eval::camera_frame& f) {
  frame_head h;
  h.tick = f.tick;
  h.pan_bits = std::bit_cast<std::uint64_t>(f.pose.pan_deg);
  h.tilt_bits = std::bit_cast<std::uint64_t>(f.pose.tilt_deg);
  h.field_of_view_bits = std::bit_cast<std::uint64_t>(f.pose.field_of_view_deg);
  h.key = key;
  h.camera = f.camera;
  h.state = static_cast<std::uint32_t>(f.state);
  h.looks = static_cast<std::uint32_t>(f.looks.size());
  h.visible = static_cast<std::uint32_t>(f.visible.size());
  return h;
}

// Rebuilds the frames from their heads and the looks and boxes that follow them; fails when
// the counts do not add up or a state is not one of frame_state's.
inline caf::error frames_of(const std::vector<frame_head>& heads,
                            std::vector<eval::look_record>& looks,
                            std::vector<eval::visible_box>& visible,
                            std::map<int, std::vector<eval::camera_frame>>& out) {
  out.clear();
  runs_of look_runs(looks);
  runs_of box_runs(visible);
  for (const auto& h : heads) {
    if (h.state > static_cast<std::uint32_t>(eval::frame_state::performing_task))
      return caf::make_error(caf::sec::invalid_argument);
    eval::camera_frame f;
    f.tick = h.tick;
    f.camera = h.camera;
    f.pose = {std::bit_cast<double>(h.pan_bits), std::bit_cast<double>(h.tilt_bits),
              std::bit_cast<double>(h.field_of_view_bits)};
    f.state = static_cast<eval::frame_state>(h.state);
    if (!look_runs.take(h.looks, f.looks) || !box_runs.take(h.visible, f.visible))
      return caf::make_error(caf::sec::invalid_argument);
    out[h.key].push_back(std::move(f));
  }
  if (!look_runs.all_taken() || !box_runs.all_taken())
    return caf::make_error(caf::sec::invalid_argument);
  return caf::error{};
}

}  // namespace detail

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, frames_wire& x) {
  if constexpr (std::is_base_of_v<caf::serializer, Inspector>) {
    std::vector<frame_head> heads;
    std::vector<eval::look_record> looks;
    std::vector<eval::visible_box> visible;
    for (const auto& [key, frames] : x.frames)
      for (const auto& frame : frames) {
        heads.push_back(detail::head_of(key, frame));
        looks.insert(looks.end(), frame.looks.begin(), frame.looks.end());
        visible.insert(visible.end(), frame.visible.begin(), frame.visible.end());
      }
    return f(as_block(heads), looks, visible);
  } else if constexpr (std::is_base_of_v<caf::deserializer, Inspector>) {
    std::vector<frame_head> heads;
    std::vector<eval::look_record> looks;
    std::vector<eval::visible_box> visible;
    if (auto err = f(as_block(heads), looks, visible)) return err;
    return detail::frames_of(heads, looks, visible, x.frames);
  } else {
    return f(x.frames);  // not a wire: printing, say
  }
}

}  // namespace argus::actors
