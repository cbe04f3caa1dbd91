#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "actors/camera_pose_board.hpp"
#include "actors/participant_info.hpp"
#include "caf/actor.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"

namespace argus::actors {

/// How the video recorder takes part in the clock: phase cameras, every tick (one video frame
/// per tick), after the world coordinator has published the tick's snapshot.
participant_info video_recorder_participant();

/// What `argus run --video` records.
struct video_settings {
  /// The mosaic video to write (MJPG in AVI); written as `<stem>.partial.avi` and renamed once the
  /// run's last tick is in it.
  std::filesystem::path file;
  /// The cameras to show, tiled in id order with their ids, like `argus feeds`.
  std::vector<config::camera_settings> cameras;
  /// Seeds each camera's imaging model (`vision::imaging_model::for_camera`).
  std::uint64_t run_seed = 0;
  /// Size of one camera's tile, pixels.
  int tile_width_px = 320;
  int tile_height_px = 240;
  /// Degrade each tile with the camera's imaging model (false: raw renderings).
  bool imaging = true;
  /// Virtual seconds per tick: the video plays at 1 / tick_seconds frames per second.
  double tick_seconds = 1.0 / 15.0;
  /// The clock's end tick: the frame of tick end_tick - 1 is the last.
  std::int64_t end_tick = 0;
  /// The render pool's front (`spawn_render_pool`).
  caf::actor render_pool;
  /// Where the camera nodes leave their poses; null: every camera at its default pose.
  std::shared_ptr<const camera_pose_board> poses;
};

/// Spawns the video recorder of a run. Its snapshots come from the world coordinator (add it
/// to `world_run_settings::snapshot_observers` with `participant_ids::video_recorder`).
///
/// At clock tick t it takes the snapshot published in phase network of t (world tick t + 1),
/// asks the render pool for every camera's frame at the snapshot's time, at the pose the camera
/// sees it from (the pose its node left on `poses` before tick t, the default pose before its
/// first turn), each camera's imaging model travelling with its request
/// so its noise is drawn in tick order whichever worker renders, tiles the answers into one
/// mosaic frame, appends it to the video and only then acknowledges the tick: the video has
/// exactly one frame per tick. A tick without a snapshot emits `video_out_of_step` and adds no
/// frame; a frame the pool fails to render emits `video_render_failed` and shows black. A camera
/// whose node did not take its turn in tick t - 1 (crashed) shows its view at its last pose,
/// marked as the key frames mark a failed camera (vision::mark_failed_feed).
///
/// The file is opened here, on the calling thread: throws std::runtime_error naming the file
/// when it cannot be written.
caf::actor spawn_video_recorder(caf::actor_system& system, video_settings settings);

}  // namespace argus::actors
