#include "actors/video_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "actors/mjpeg_avi_writer.hpp"
#include "actors/ordered_inbox.hpp"
#include "actors/participant_ids.hpp"
#include "actors/render_pool.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "actors/video_tiles.hpp"
#include "fmt/format.h"
#include "vision/feed_mosaic.hpp"
#include "vision/imaging_model.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::actors {
namespace {

// Gap between tiles, pixels (as `argus feeds`).

struct video_file {
  std::filesystem::path final_path;
  std::filesystem::path partial_path;
  std::optional<mjpeg_avi_writer> writer;
};

/// One camera as the recorder sees it: where it looks and its imaging model, which is away
/// (travelling with a request) while its frame is being rendered.
struct recorded_camera {
  int id = 0;
  vision::camera_view view;
  std::optional<vision::imaging_model> imaging;
  config::imaging_model imaging_settings;
  cv::Rect tile;
  /// Its node missed its last turn: the tile is marked failed, as in the key frames.
  bool down = false;
};

struct video_recorder_state {
  participant_info info;
  video_settings settings;
  /// Null once the file is complete (or for none); shared only to pass it into the actor.
  std::shared_ptr<video_file> file;
  std::vector<recorded_camera> cameras;
  ordered_inbox<std::shared_ptr<const world::snapshot>> snapshots;
  /// The frame being assembled and what the tick waits for.
  cv::Mat mosaic;
  std::size_t pending = 0;
  std::optional<tick_context> ctx;
  caf::actor clock;
};

// Appends the assembled frame; after the last tick the file is closed and gets its name.
void finish_tick(caf::stateful_actor<video_recorder_state>* self) {
  auto& st = self->state;
  if (st.file) {
    st.file->writer->write(st.mosaic);
    if (st.ctx->tick() + 1 >= st.settings.end_tick) {
      st.file->writer->close();
      std::error_code ignored;
      std::filesystem::rename(st.file->partial_path, st.file->final_path, ignored);
      st.file.reset();
    }
  }
  self->send(st.clock, std::move(*st.ctx).finish());
  st.ctx.reset();
  st.clock = nullptr;
}

void tile_done(caf::stateful_actor<video_recorder_state>* self, std::size_t k, cv::Mat image) {
  auto& st = self->state;
  auto& camera = st.cameras[k];
  if (image.empty()) image = cv::Mat(camera.tile.size(), CV_8UC3, cv::Scalar(0, 0, 0));
  if (camera.down) vision::mark_failed_feed(image);
  vision::label_feed(image, camera.id);
  image.copyTo(st.mosaic(camera.tile));
  if (--st.pending == 0) finish_tick(self);
}

void record_tick(caf::stateful_actor<video_recorder_state>* self,
                 const std::shared_ptr<const world::snapshot>& frame) {
  auto& st = self->state;
  st.mosaic.setTo(cv::Scalar(0, 0, 0));
  st.pending = st.cameras.size();
  const double time_s = frame->time().count();
  const auto tick = st.ctx->tick();
  for (std::size_t k = 0; k < st.cameras.size(); ++k) {
    auto& camera = st.cameras[k];
    render_request request;
    request.camera = camera.id;
    request.view = camera.view;
    camera.down = false;
    if (st.settings.poses) {
      if (const auto seen = st.settings.poses->before(camera.id, tick)) {
        request.view.pose = seen->pose;
        camera.down = seen->tick < tick - 1;
      }
    }
    request.frame = frame;
    request.time_s = time_s;
    request.field_interval_s = st.settings.tick_seconds / 2.0;
    request.imaging = std::move(camera.imaging);
    self->request(st.settings.render_pool, caf::infinite, render_atom_v, std::move(request))
        .then(
            [self, k](render_result& result) {
              self->state.cameras[k].imaging = std::move(result.imaging);
              tile_done(self, k, std::move(result.image));
            },
            [self, k](caf::error& err) {
              auto& st = self->state;
              // The camera's RNG went down with the request: its noise restarts from its seed
              // (the run is broken anyway; the event says so).
              if (st.settings.imaging)
                st.cameras[k].imaging = vision::imaging_model::for_camera(
                    st.cameras[k].imaging_settings, st.settings.run_seed, st.cameras[k].id);
              st.ctx->emit(events::video_render_failed{.camera = st.cameras[k].id,
                                                       .error_code = static_cast<int>(err.code())});
              tile_done(self, k, {});
            });
  }
  if (st.cameras.empty()) finish_tick(self);
}

caf::behavior video_recorder(caf::stateful_actor<video_recorder_state>* self,
                             video_settings settings, std::shared_ptr<video_file> file) {
  auto& st = self->state;
  st.info = video_recorder_participant();
  st.file = std::move(file);
  auto cameras = settings.cameras;
  std::sort(cameras.begin(), cameras.end(),
            [](const auto& a, const auto& b) { return a.id < b.id; });
  const auto layout = vision::feed_mosaic_layout::for_feeds(cameras.size(), settings.tile_width_px,
                                                            settings.tile_height_px);
  st.mosaic = cv::Mat(layout.size(), CV_8UC3, cv::Scalar(0, 0, 0));
  const video_tile_settings tiles{settings.tile_width_px, settings.tile_height_px,
                                  settings.imaging};
  for (std::size_t k = 0; k < cameras.size(); ++k) {
    const auto& c = cameras[k];
    recorded_camera rc;
    rc.id = c.id;
    rc.view = {vision::camera_placement::from(c), vision::ptz_camera::from(c).state(),
               settings.tile_width_px, settings.tile_height_px};
    if (settings.imaging) {
      rc.imaging = video_imaging_model(c, tiles, settings.run_seed);
      rc.imaging_settings = rc.imaging->settings();
    }
    rc.tile = layout.tile(k);
    st.cameras.push_back(std::move(rc));
  }
  st.settings = std::move(settings);
  return {
      [self](world_snapshot_atom, const mail_stamp& stamp,
             std::shared_ptr<const world::snapshot>& frame) {
        self->state.snapshots.put(stamp, std::move(frame));
      },
      [self](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t) {
        auto& st = self->state;
        st.ctx.emplace(st.info.id, st.info.name, tick, st.info.tick_phase);
        st.clock = caf::actor_cast<caf::actor>(self->current_sender());
        std::shared_ptr<const world::snapshot> latest;
        for (auto& [stamp, frame] : st.snapshots.take_due(tick, p)) latest = std::move(frame);
        if (!latest) {
          st.ctx->emit(events::video_out_of_step{.tick = tick});
          self->send(st.clock, std::move(*st.ctx).finish());
          st.ctx.reset();
          st.clock = nullptr;
          return;
        }
        record_tick(self, latest);
      },
  };
}

}  // namespace

participant_info video_recorder_participant() {
  participant_info info;
  info.id = participant_ids::video_recorder;
  info.name = "video";
  info.tick_phase = phase::cameras;
  info.mode = wake_mode::every_tick;
  return info;
}

caf::actor spawn_video_recorder(caf::actor_system& system, video_settings settings) {
  if (settings.tick_seconds <= 0.0) throw std::invalid_argument("video: tick must be positive");
  if (settings.tile_width_px < 16 || settings.tile_height_px < 16)
    throw std::invalid_argument("video: tiles must be at least 16x16 pixels");
  auto file = std::make_shared<video_file>();
  file->final_path = settings.file;
  // `feeds.partial.avi` rather than `feeds.avi.partial`: players go by the extension.
  file->partial_path = settings.file;
  file->partial_path.replace_extension(".partial" + settings.file.extension().string());
  std::error_code ignored;
  if (settings.file.has_parent_path())
    std::filesystem::create_directories(settings.file.parent_path(), ignored);
  const auto size = vision::feed_mosaic_layout::for_feeds(
                        settings.cameras.size(), settings.tile_width_px, settings.tile_height_px)
                        .size();
  file->writer.emplace(file->partial_path, 1.0 / settings.tick_seconds, size);
  return system.spawn(video_recorder, std::move(settings), std::move(file));
}

}  // namespace argus::actors
