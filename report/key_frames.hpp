#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "report/event_log.hpp"

namespace argus::report {

/// One camera's frame at a key event: which camera, and which world tick's frame it is.
struct key_frame {
  int camera = -1;
  /// The world tick of the frame shown (a snapshot's tick, as poses.csv and tracks.csv count).
  std::int64_t world_tick = 0;
  /// The camera failed at this event: its frame is its last one, shown greyed and marked.
  bool failed = false;
};

/// A moment of the run worth a picture (paper Fig. 18): a task's start, a hand-off, a change of
/// leader, a camera's failure or its recovery, with the frames of the cameras concerned.
struct key_event {
  /// Virtual time of the event, seconds, and its clock tick (events.jsonl's "t" and "tick").
  double time_s = 0.0;
  std::int64_t tick = 0;
  /// "task_created", "handoff", "leader_changed", "camera_failed" or "camera_recovered".
  std::string kind;
  /// The task it concerns, -1 for a failure or a recovery.
  int task = -1;
  /// What a caption adds to the kind: "7 -> 6", "leader 2 (was 6, leader_timeout)".
  std::string detail;
  /// One frame per camera concerned (two for a hand-off: the giver's and the taker's).
  std::vector<key_frame> frames;
};

/// The world tick a camera saw at clock tick `tick`: clock tick t runs world tick t + 1 before
/// the cameras' phase (actors/world_coordinator.hpp), so a camera's turn at t looks at the
/// snapshot of world tick t + 1.
constexpr std::int64_t world_tick_seen_at(std::int64_t tick) noexcept {
  return tick + 1;
}

/// The key events of a run's log, in time order (by tick; log order among equals):
///
/// | event                                      | key event          | frames                   |
/// | ------------------------------------------ | ------------------ | ------------------------ |
/// | `task_created`                             | `task_created`     | the creating camera      |
/// | `handoff`                                  | `handoff`          | `from`, then `to`        |
/// | `leader_changed`                           | `leader_changed`   | the new leader           |
/// | `fault` crash / crash_and_recover, applied | `camera_failed`    | the camera's last frame  |
/// | `node_recovered`, applied                  | `camera_recovered` | the camera's first frame |
///
/// A camera's frame at an event of clock tick t is the one of its turn at t (world tick t + 1);
/// a failed camera's last frame is the one of its turn at t - 1 (faults strike before the
/// cameras' phase), world tick t. Link faults are not camera failures and are left out, as are
/// faults not applied (the camera was already down) and events without a tick or a camera.
std::vector<key_event> key_events_of(const event_log& log);

/// The key events a contact sheet shows when it may hold at most `max_frames` frames.
struct key_event_selection {
  std::vector<key_event> shown;
  /// Events and frames left out to stay within the cap.
  std::size_t events_left_out = 0;
  std::size_t frames_left_out = 0;
};

/// All of `events` when their frames number at most `max_frames`; else the most events, spread
/// evenly over the log (event i * (n - 1) / (k - 1), rounded, for i = 0 .. k - 1, so the first
/// and the last are always in), whose frames fit. An event's frames are kept together.
key_event_selection select_key_events(std::vector<key_event> events, std::size_t max_frames);

}  // namespace argus::report
