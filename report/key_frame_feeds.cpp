#include "report/key_frame_feeds.hpp"

#include <opencv2/imgcodecs.hpp>
#include <set>

#include "fmt/format.h"
#include "report/binary_file.hpp"
#include "report/camera_logs.hpp"
#include "report/contact_sheet.hpp"
#include "report/feed_frames.hpp"
#include "report/key_frames.hpp"

namespace argus::report {

namespace {

// How long after a task's event the picture may wait for the camera's first look: a camera
// takes it on its next turn or the one after; half a second is plenty and keeps the picture
// at the event.
constexpr double settle_window_s = 0.5;

std::string label_of(const std::string& kind) {
  if (kind == "task_created") return "task start";
  if (kind == "handoff") return "handoff";
  if (kind == "leader_changed") return "leader change";
  if (kind == "camera_failed") return "camera failure";
  if (kind == "camera_recovered") return "recovery";
  return kind;
}

// The caption's lines for frame `k` of `e`: when and what, whose frame of when, and how.
std::vector<std::string> caption_of(const key_event& e, std::size_t k, double tick_s) {
  const auto& f = e.frames[k];
  std::string first = fmt::format("{:.2f} s  {}", e.time_s, label_of(e.kind));
  if (e.task >= 0) first += fmt::format("  task {}", e.task);
  std::string second = fmt::format("camera {}  frame {:.2f} s", f.camera,
                                   static_cast<double>(f.world_tick) * tick_s);
  std::string third = e.detail;
  if (e.kind == "handoff") third += k == 0 ? " (gives)" : " (takes)";
  if (f.failed) third += ": last frame";
  return {first, second, third};
}

std::vector<unsigned char> png_of(const cv::Mat& image) {
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", image, png)) throw std::runtime_error("cannot encode a PNG");
  return png;
}

}  // namespace

feeds_outcome write_feeds(const std::filesystem::path& dir, const config::scenario& scenario,
                          const std::shared_ptr<const world::station>& station,
                          const event_log& log, std::size_t max_frames) {
  feeds_outcome out;
  const auto folder = dir / "feeds";
  // Ours alone: an earlier drawing's frames must not linger beside this one's.
  std::filesystem::remove_all(folder);
  auto events = key_events_of(log);
  if (events.empty()) {
    out.left_out.push_back(
        "feeds/ (no key event in events.jsonl: no task started, no camera failed)");
    return out;
  }
  std::optional<pose_history> poses;
  std::optional<track_history> tracks;
  try {
    poses = pose_history::read(dir / "poses.csv");
    tracks = track_history::read(dir / "tracks.csv");
  } catch (const camera_log_error& e) {
    out.left_out.push_back(fmt::format("feeds/ ({})", e.what()));
    return out;
  }
  const double tick_s = scenario.run.tick.count();
  auto selection = select_key_events(std::move(events), max_frames);
  settle_on_first_report(selection.shown, *tracks,
                         static_cast<std::int64_t>(settle_window_s / tick_s + 0.5));
  std::vector<std::vector<cv::Mat>> frames;
  try {
    frames = render_key_frames(scenario, station, selection.shown, *poses, *tracks);
  } catch (const std::exception& e) {
    // No EGL device (a machine without Mesa's or a GPU's EGL): the run is not failed by it.
    out.left_out.push_back(fmt::format("feeds/ (cannot render: {})", e.what()));
    return out;
  }

  std::filesystem::create_directories(folder);
  std::vector<contact_sheet_tile> tiles;
  std::set<std::string> names;
  report_image sheet{"feeds/contact_sheet.png", "", {}, {}};
  for (std::size_t e = 0; e < selection.shown.size(); ++e) {
    const auto& event = selection.shown[e];
    for (std::size_t k = 0; k < event.frames.size(); ++k) {
      const auto stem =
          fmt::format("t{:07.2f}_{}_cam{}", event.time_s, event.kind, event.frames[k].camera);
      auto name = stem + ".png";
      for (int n = 2; !names.insert(name).second; ++n) name = fmt::format("{}_{}.png", stem, n);
      const auto file = folder / name;
      write_file(file, png_of(frames[e][k]));
      out.written.push_back(file);
      auto caption = caption_of(event, k, tick_s);
      sheet.details.push_back(
          fmt::format("feeds/{}: {}; {}; {}", name, caption[0], caption[1], caption[2]));
      tiles.push_back({std::move(frames[e][k]), std::move(caption)});
    }
  }
  std::string note;
  if (selection.frames_left_out > 0)
    note = fmt::format(
        "{} of {} frames shown: {} frames of {} key events left out (at most {} frames, chosen "
        "evenly over the run)",
        tiles.size(), tiles.size() + selection.frames_left_out, selection.frames_left_out,
        selection.events_left_out, max_frames);
  const std::string title = fmt::format("{}: the cameras' frames at the key events", scenario.name);
  sheet.png = png_of(render_contact_sheet(tiles, title, note));
  sheet.caption = note.empty()
                      ? fmt::format("the cameras' frames at the run's {} key events ({} frames)",
                                    selection.shown.size(), tiles.size())
                      : "the cameras' frames at the key events; " + note;
  const auto sheet_file = folder / "contact_sheet.png";
  write_file(sheet_file, sheet.png);
  out.written.push_back(sheet_file);
  out.sheet = std::move(sheet);
  return out;
}

}  // namespace argus::report
