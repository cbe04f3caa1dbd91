#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "config/scenario.hpp"
#include "live/console_state.hpp"
#include "nlohmann/json.hpp"
#include "vision/imaging_model.hpp"
#include "vision/renderer.hpp"
#include "world/station.hpp"

namespace argus::serve {

/// One camera's feed as the page gets it: a JPEG and where it came from.
struct feed_image {
  std::vector<unsigned char> jpeg;
  std::int64_t tick = 0;
  /// "node": the node's own degraded frame with its tracker's boxes; "display": rendered for
  /// the page alone (the node looked at nothing this tick: an idle node renders nothing).
  std::string source;
};

/// Makes the JPEG feeds of the live console. Where the node sensed a frame lately it sends
/// that, with the tracker's boxes drawn; otherwise it renders the camera's view at its current
/// pose from the latest snapshot with a renderer (EGL context) of its own and degrades it with
/// imaging models of its own (seeded apart from the nodes'): a display-only path that takes
/// nothing from the run — no RNG draw, no render-pool slot, no wait. One frame at a time
/// (a lock): a client that asks faster waits, and the page asks for the next frame only when it
/// has shown the last, so frames are dropped, never queued.
class feed_renderer {
 public:
  /// For `scenario`'s cameras in `where`. Its renderer (an EGL context) is made when it first
  /// renders: a console nobody watches costs no context.
  feed_renderer(const config::scenario& scenario, std::shared_ptr<const world::station> where);

  /// Camera `camera`'s current feed, or nothing for an unknown camera, a crashed one, or before
  /// the first snapshot. Throws std::runtime_error when it must render and no EGL device works.
  std::optional<feed_image> frame(int camera, const live::console_state& console);

  /// The pedestrians in camera `camera`'s view at the latest snapshot, by ground truth: id and
  /// box in the frame ([x, y, width, height] pixels). For tests and tools that must click on
  /// someone; the page does not use it. Nothing for an unknown camera or before the first
  /// snapshot.
  std::optional<nlohmann::json> people(int camera, const live::console_state& console) const;

 private:
  vision::camera_view view_of(int camera, const live::camera_pose& pose) const;

  std::shared_ptr<const world::station> station_;
  std::mutex mutex_;
  std::map<int, config::camera_settings> cameras_;
  std::map<int, vision::imaging_model> imaging_;
  std::optional<vision::renderer> renderer_;
  double tick_seconds_ = 1.0 / 15.0;
};

}  // namespace argus::serve
