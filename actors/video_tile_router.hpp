#pragma once

#include <cstddef>
#include <map>
#include <memory>

#include "caf/actor.hpp"
#include "caf/fwd.hpp"
#include "world/station.hpp"

namespace argus::actors {

/// Where a distributed run's video tiles are rendered (docs/distributed.md, "Video").
struct video_tile_routes {
  /// The worker host of each camera (`spawn_worker_host`, a proxy when remote): it renders that
  /// camera's tiles from the snapshot on its board.
  std::map<int, caf::actor> hosts;
  /// For tiles rendered here: those of a camera no worker hosts, and those of a lost worker's
  /// cameras.
  std::shared_ptr<const world::station> station;
  /// Renderers of the render pool made here the first time a tile needs one (>= 1).
  std::size_t local_renderers = 1;
};

/// Spawns the video recorder's render pool for a distributed run: a front that takes
/// `(render_atom, render_request)` as `spawn_render_pool`'s does, and answers the same
/// `render_result`, the same to the byte, but has each camera's tile rendered by the worker that
/// hosts the camera (`video_tile_atom`, actors/video_tiles.hpp): only the pose, the time and the
/// noise state go out, and only the tile's pixels come back.
///
/// It watches the hosts. A tile whose worker is lost (ended, or its connection broken) before
/// it answers, and every later tile of that worker's cameras, is rendered here from the
/// request it kept (the snapshot and the imaging model as they went out), so the video goes on
/// with the same pixels. An error the worker answers with is passed on.
///
/// Ended, it ends the render pool it made.
caf::actor spawn_video_tile_router(caf::actor_system& system, video_tile_routes routes);

}  // namespace argus::actors
