#pragma once

#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "actors/render_pool.hpp"

namespace argus::vision {
class renderer;
}  // namespace argus::vision

namespace argus::actors {

/// Renderers (EGL contexts) lent to whichever thread asks: a camera node renders its own frame
/// inside its turn, on the scheduler thread that runs it, instead of mailing a render worker
/// and waiting for the answer.
///
/// Why: in a pixel run every node that senses waits for its frame before it can finish its
/// turn, so the scheduler threads had nothing to do while the render workers worked, yet they
/// polled for work beside them; on two cores the hand-over to a worker thread and back, and
/// the polling, cost about a quarter of the render pool's throughput (bench/RESULTS.md, "Pixels
/// at speed"). Rendered here, a frame costs its rendering and nothing else, and the turns of a
/// tick spread over the scheduler's threads as any other work does.
///
/// The pixels are the same as the render pool's: `render_frame` on any renderer, with the
/// camera's own imaging model travelling with the request.
///
/// Thread-safe. With as many renderers as scheduler threads no caller ever waits; with fewer,
/// a caller waits for one to come back.
class shared_renderers {
 public:
  /// `count` (>= 1) renderers of `station`, made here, on the calling thread, so that a machine
  /// without a working EGL device fails here with std::runtime_error.
  shared_renderers(std::shared_ptr<const world::station> station, std::size_t count);
  ~shared_renderers();
  shared_renderers(const shared_renderers&) = delete;
  shared_renderers& operator=(const shared_renderers&) = delete;

  /// Renders `request` on a free renderer (waiting for one if none is free). Throws what the
  /// renderer throws; the renderer is returned either way.
  render_result render(render_request request);

 private:
  std::vector<std::unique_ptr<vision::renderer>> all_;
  std::mutex mutex_;
  std::condition_variable returned_;
  std::vector<std::size_t> free_;
};

}  // namespace argus::actors
