#pragma once

// A camera's video tile as it crosses between the coordinator and the worker that renders it
// (docs/distributed.md, "Video"). The world's snapshot does not cross: the worker already holds
// it on its board, the same to the byte. Neither does the imaging model: both ends make it from
// the scenario, and only where its noise stands crosses, so the worker draws the camera's noise
// exactly where one process would.

#include <cstdint>
#include <vector>

#include "actors/render_pool.hpp"
#include "actors/wire_double.hpp"
#include "actors/wire_log.hpp"
#include "config/scenario.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::actors {

/// What a worker needs to render the video's tiles of its cameras (`worker_setup::video`).
struct video_tile_settings {
  /// Size of one tile, pixels; 0 when the run records no video on its workers.
  int width_px = 0;
  int height_px = 0;
  /// Whether tiles are degraded by the cameras' imaging models (video_settings::imaging).
  bool imaging = true;

  bool on() const noexcept { return width_px > 0 && height_px > 0; }
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, video_tile_settings& x) {
  return f(x.width_px, x.height_px, x.imaging);
}

/// One tile to render: camera `camera` at `pose`, looking at the snapshot of virtual time
/// `time_s` (the one on the worker's board).
struct video_tile_request {
  int camera = 0;
  vision::ptz_state pose;
  double time_s = 0.0;
  double field_interval_s = 0.0;
  /// Whether the tile is degraded, and where the camera's noise stands before it.
  bool imaging = false;
  std::uint64_t noise_state = 0;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, video_tile_request& x) {
  return f(x.camera, x.pose, as_bits(x.time_s), as_bits(x.field_interval_s), x.imaging,
           x.noise_state);
}

/// A rendered tile and where the camera's noise stands after it. Its pixels travel as the JPEG
/// encoding the camera's imaging model made as its last step, when it made one (decoding it gives
/// the same pixels, and it is about a tenth of their size); otherwise as BGR rows.
struct video_tile {
  int width_px = 0;
  int height_px = 0;
  bool jpeg = false;
  std::vector<std::uint8_t> bytes;
  std::uint64_t noise_state = 0;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, video_tile& x) {
  return f(x.width_px, x.height_px, x.jpeg, x.bytes, x.noise_state);
}

/// The request for `request`'s tile that crosses to a worker (the camera, its pose, the time and
/// its noise state). Its snapshot stays here.
video_tile_request to_tile_request(const render_request& request);

/// The worker's side: the render request for `tile` of `camera`, seen in `settings` and looking
/// at `frame`; `imaging` (when the tile is degraded) is the camera's video imaging model, made
/// by `video_imaging_model`, and leaves with the request at the tile's noise state. Throws
/// std::invalid_argument when `frame`'s time is not the tile's.
render_request from_tile_request(const video_tile_request& tile,
                                 const config::camera_settings& camera,
                                 const video_tile_settings& settings,
                                 std::shared_ptr<const world::snapshot> frame,
                                 std::optional<vision::imaging_model> imaging);

/// The imaging model a video tile of `camera` is degraded with: the camera's own, at the tile's
/// size, seeded from `run_seed` (what the video recorder makes, in one process or not).
vision::imaging_model video_imaging_model(const config::camera_settings& camera,
                                          const video_tile_settings& settings,
                                          std::uint64_t run_seed);

/// The worker's answer for a rendered `result` (a BGR frame, continuous or not).
video_tile to_tile(const render_result& result);

/// The coordinator's side: the render result for `tile`, with `imaging` (the model that went
/// out with the request, or none) advanced to the tile's noise state. Throws
/// std::invalid_argument when the tile's bytes do not decode to its size.
render_result from_tile(video_tile tile, std::optional<vision::imaging_model> imaging);

}  // namespace argus::actors
