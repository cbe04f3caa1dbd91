#include "report/feed_frames.hpp"

#include <algorithm>
#include <exception>
#include <map>
#include <opencv2/imgproc.hpp>
#include <thread>

#include "config/derive_seed.hpp"
#include "fmt/format.h"
#include "vision/capture.hpp"
#include "vision/feed_mosaic.hpp"
#include "vision/imaging_model.hpp"
#include "vision/ptz_camera.hpp"
#include "vision/renderer.hpp"
#include "world/crowd.hpp"

namespace argus::report {

namespace {

// Tags the noise seeds of the feeds apart from every actor's ("feed").
constexpr std::uint64_t feeds_seed_tag = 0x66656564;

const config::camera_settings* camera_of(const config::scenario& scenario, int id) {
  for (const auto& c : scenario.cameras)
    if (c.id == id) return &c;
  return nullptr;
}

void draw_boxes(cv::Mat& image, const std::vector<track_box>& boxes) {
  int lost_row = 0;
  for (const auto& box : boxes) {
    const auto colour = box.observed ? observed_box_colour : unobserved_box_colour;
    if (!box.found) {
      vision::draw_feed_label(image, fmt::format("task {} lost", box.task),
                              {4, image.rows - 6 - 22 * lost_row++}, unobserved_box_colour);
      continue;
    }
    const cv::Rect rect(cv::Point(static_cast<int>(box.x), static_cast<int>(box.y)),
                        cv::Size(std::max(1, static_cast<int>(box.width)),
                                 std::max(1, static_cast<int>(box.height))));
    // No anti-aliasing: the box keeps its pure colour.
    cv::rectangle(image, rect, colour, 2, cv::LINE_8);
    vision::draw_feed_label(image, fmt::format("task {}", box.task), {rect.x, rect.y - 3}, colour);
  }
}

cv::Mat missing_camera(int id) {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(40, 40, 40));
  vision::draw_feed_label(image, fmt::format("no camera {} in the scenario", id), {8, 120},
                          {255, 255, 255});
  return image;
}

// Where each frame of each event goes.
struct frame_slot {
  std::size_t event = 0;
  std::size_t frame = 0;
};

}  // namespace

void settle_on_first_report(std::vector<key_event>& events, const track_history& tracks,
                            std::int64_t window_ticks) {
  for (auto& e : events) {
    if (e.task < 0) continue;
    for (auto& f : e.frames) {
      if (f.failed) continue;
      const auto first = tracks.first_report(
          f.camera, e.task, f.world_tick, f.world_tick + std::max<std::int64_t>(window_ticks, 0));
      if (first >= 0) f.world_tick = first;
    }
  }
}

namespace {

std::vector<std::vector<cv::Mat>> render_on_this_thread(
    const config::scenario& scenario, const std::shared_ptr<const world::station>& station,
    const std::vector<key_event>& events, const pose_history& poses, const track_history& tracks) {
  std::vector<std::vector<cv::Mat>> out(events.size());
  std::map<std::int64_t, std::vector<frame_slot>> by_tick;
  for (std::size_t e = 0; e < events.size(); ++e) {
    out[e].resize(events[e].frames.size());
    for (std::size_t f = 0; f < events[e].frames.size(); ++f)
      by_tick[std::max<std::int64_t>(events[e].frames[f].world_tick, 0)].push_back({e, f});
  }
  if (by_tick.empty()) return out;

  vision::renderer renderer(station);
  const double tick_s = scenario.run.tick.count();
  // One pass over time: the crowd is stepped once, whatever the number of frames.
  world::crowd crowd(station, world::crowd_settings::from(scenario));
  std::int64_t now = 0;
  for (const auto& [tick, slots] : by_tick) {
    for (; now < tick; ++now) crowd.step();
    const auto& snapshot = *crowd.current();
    const double time_s = snapshot.time().count();
    for (const auto& slot : slots) {
      const auto& frame = events[slot.event].frames[slot.frame];
      const auto* camera = camera_of(scenario, frame.camera);
      if (camera == nullptr) {
        out[slot.event][slot.frame] = missing_camera(frame.camera);
        continue;
      }
      vision::ptz_state pose = vision::ptz_camera::from(*camera).state();
      if (const auto* logged = poses.at(frame.camera, tick))
        pose = {logged->pan_deg, logged->tilt_deg, logged->field_of_view_deg};
      const vision::camera_view view{vision::camera_placement::from(*camera), pose,
                                     static_cast<int>(camera->imaging.width_px),
                                     static_cast<int>(camera->imaging.height_px)};
      auto model = vision::imaging_model::for_camera(
          camera->imaging,
          config::derive_seed(config::derive_seed(scenario.run.seed, feeds_seed_tag),
                              static_cast<std::uint64_t>(tick)),
          camera->id);
      cv::Mat image = vision::capture(renderer, view, snapshot, time_s, tick_s / 2.0, model);
      if (frame.failed) vision::mark_failed_feed(image);
      draw_boxes(image, tracks.at(frame.camera, tick));
      vision::label_feed(image, frame.camera);
      out[slot.event][slot.frame] = std::move(image);
    }
  }
  return out;
}

}  // namespace

std::vector<std::vector<cv::Mat>> render_key_frames(
    const config::scenario& scenario, const std::shared_ptr<const world::station>& station,
    const std::vector<key_event>& events, const pose_history& poses, const track_history& tracks) {
  // On a thread of its own, ended before this returns. The OpenGL driver's thread-local
  // storage goes with it; left in the main thread, which lives until exit, LeakSanitizer's
  // exit-time scan read a stale entry of it and crashed in most ASan runs that wrote feeds/.
  std::vector<std::vector<cv::Mat>> out;
  std::exception_ptr error;
  std::thread renderer_thread([&] {
    try {
      out = render_on_this_thread(scenario, station, events, poses, tracks);
    } catch (...) {
      error = std::current_exception();
    }
  });
  renderer_thread.join();
  if (error) std::rethrow_exception(error);
  return out;
}

}  // namespace argus::report
