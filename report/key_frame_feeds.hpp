#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/scenario.hpp"
#include "report/event_log.hpp"
#include "report/html_report.hpp"

namespace argus::world {
class station;
}  // namespace argus::world

namespace argus::report {

/// The most frames a contact sheet holds: enough for a long run's story, small enough for a
/// page (48 frames of 240 x 180).
inline constexpr std::size_t contact_sheet_max_frames = 48;

/// What write_feeds wrote, what it left out and why, and the sheet for the page.
struct feeds_outcome {
  std::vector<std::filesystem::path> written;
  std::vector<std::string> left_out;
  /// contact_sheet.png with one detail line per frame (and the note on frames left out);
  /// nothing when the feeds were left out.
  std::optional<report_image> sheet;
};

/// Writes `dir/feeds/` (docs/reports.md): one PNG per frame of each key event
/// (report/key_frames.hpp) as its camera saw it (report/feed_frames.hpp), named so that the
/// names sort by time (`t0016.00_task_created_cam7.png`), and `contact_sheet.png` tiling them
/// with captions (time, event, camera, task), at most `max_frames` of them, spread evenly over
/// the run, saying how many were left out. Reads events.jsonl's `log`, `dir/poses.csv` and
/// `dir/tracks.csv`; writes nothing else. The folder is cleared first, so a redraw leaves no
/// frame of an earlier drawing. Leaves the feeds out, saying why in `left_out` (no key event,
/// a missing or bad poses.csv or tracks.csv, naming the file and line, no EGL renderer), rather
/// than throw; throws only when a file cannot be written.
feeds_outcome write_feeds(const std::filesystem::path& dir, const config::scenario& scenario,
                          const std::shared_ptr<const world::station>& station,
                          const event_log& log, std::size_t max_frames = contact_sheet_max_frames);

}  // namespace argus::report
