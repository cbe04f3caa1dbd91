#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <vector>

#include "caf/actor.hpp"
#include "caf/allowed_unsafe_message_type.hpp"
#include "caf/fwd.hpp"
#include "vision/imaging_model.hpp"
#include "vision/ptz_camera.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::vision {
class renderer;
}  // namespace argus::vision

namespace argus::actors {

/// One frame to render: a camera's view of a snapshot at a virtual time, optionally degraded.
///
/// The imaging model travels with the request and comes back, advanced, in the answer: its
/// RNG is the camera's own (`vision::imaging_model::for_camera`), and a requester that keeps
/// at most one frame per camera in flight (the video recorder asks once per camera per tick)
/// draws that camera's noise in tick order, whichever worker renders — the same bytes as a
/// direct `vision::renderer` + `imaging_model` applied frame after frame.
struct render_request {
  vision::camera_view view;
  std::shared_ptr<const world::snapshot> frame;
  /// Virtual time of the (first) field, seconds; drives the gait.
  double time_s = 0.0;
  /// Virtual seconds between the two fields of an interlaced frame (half a tick).
  double field_interval_s = 0.0;
  /// The camera's imaging model; none for the raw rendering.
  std::optional<vision::imaging_model> imaging;
  /// The camera it shows: a distributed run renders it on that camera's worker
  /// (actors/video_tile_router.hpp).
  int camera = 0;
};

/// A rendered frame: the (degraded) BGR image, the imaging model advanced past it (to send
/// with the camera's next request), and which worker rendered it (for tests and logs only:
/// it never influences the pixels).
struct render_result {
  cv::Mat image;
  std::optional<vision::imaging_model> imaging;
  std::size_t worker = 0;
};

/// The render pool of a run: `front` takes `(render_atom, render_request)` and answers with a
/// `render_result`.
struct render_pool {
  caf::actor front;
  /// Number of workers (renderers).
  std::size_t size = 0;
};

/// Spawns `workers` (>= 1) detached render actors — each its own thread and its own
/// `vision::renderer`, hence its own EGL context — and a front that hands each request to the
/// least loaded worker (fewest requests in flight; the lowest index among equals) and relays
/// the answer. The renderers are created here, on the calling thread, so a machine without a
/// working EGL device fails the spawn with std::runtime_error rather than a dead actor.
///
/// The workers are linked to the front: `caf::anon_send_exit(pool.front, ...)` ends them all.
/// A request whose worker fails is answered with the error.
render_pool spawn_render_pool(caf::actor_system& system,
                              std::shared_ptr<const world::station> station, std::size_t workers);

/// Renders `request` on `renderer` (what a worker does; also the reference the tests compare
/// the pool against): both fields when the imaging model interlaces, then the imaging model.
render_result render_frame(vision::renderer& renderer, render_request request);

}  // namespace argus::actors

// Heavy payloads that never leave the process: a request shares the whole snapshot by pointer
// (copying it per camera is what the pointer avoids) and carries the camera's live RNG state;
// an answer holds a full frame whose pixels are reference-counted by cv::Mat. Local mail moves
// them without serialization, so they are allowed unsafe rather than given an inspect().
CAF_ALLOW_UNSAFE_MESSAGE_TYPE(argus::actors::render_request)
CAF_ALLOW_UNSAFE_MESSAGE_TYPE(argus::actors::render_result)
// The snapshot the world coordinator publishes to observers (the video recorder) each tick.
CAF_ALLOW_UNSAFE_MESSAGE_TYPE(std::shared_ptr<const argus::world::snapshot>)
