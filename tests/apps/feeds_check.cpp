// Checks the feeds/ folder `argus run` left in a run's folder; exit 0 when it shows what it must.
//   feeds_check DIR        one PNG per frame of the key events events.jsonl holds (capped as the
//                          run caps them), each a camera's view; contact_sheet.png with that
//                          many tiles; the tracker's box drawn on the task's first frame;
//                          report.html showing the sheet
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>

#include "report/contact_sheet.hpp"
#include "report/feed_frames.hpp"
#include "report/key_frame_feeds.hpp"
#include "report/key_frames.hpp"
#include "support/scene_checks.hpp"

namespace {

using namespace argus;

bool check(bool ok, const std::string& what) {
  std::printf("%s %s\n", ok ? "ok:  " : "FAIL:", what.c_str());
  return ok;
}

// Pixels of exactly `colour`: the box is drawn without anti-aliasing in a pure colour.
int pixels_of(const cv::Mat& image, const cv::Scalar& colour) {
  cv::Mat mask;
  cv::inRange(image, colour, colour, mask);
  return cv::countNonZero(mask);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const std::filesystem::path dir = argv[1];
  const auto log = report::event_log::read(dir / "events.jsonl");
  if (!check(log.has_value(), "events.jsonl read")) return 1;
  const auto selection =
      report::select_key_events(report::key_events_of(*log), report::contact_sheet_max_frames);
  std::size_t frames = 0;
  for (const auto& e : selection.shown) frames += e.frames.size();
  bool ok = check(frames > 0, std::to_string(frames) + " key frames expected");

  std::size_t pngs = 0;
  std::size_t boxed_task_starts = 0;
  std::size_t task_starts = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "feeds")) {
    const auto name = entry.path().filename().string();
    if (name == "contact_sheet.png") continue;
    ++pngs;
    const cv::Mat image = cv::imread(entry.path().string(), cv::IMREAD_COLOR);
    const auto s = test_support::statistics_of(image);
    ok &= check(!image.empty() && test_support::shows_a_scene(s), name + " shows a scene");
    if (name.find("_task_created_") != std::string::npos) {
      ++task_starts;
      const int observed = pixels_of(image, report::observed_box_colour);
      const int unobserved = pixels_of(image, report::unobserved_box_colour);
      ok &= check(observed + unobserved >= 40, name + ": tracker box drawn (" +
                                                   std::to_string(observed) + " green, " +
                                                   std::to_string(unobserved) + " red pixels)");
      if (observed + unobserved >= 40) ++boxed_task_starts;
    }
  }
  ok &= check(pngs == frames,
              std::to_string(pngs) + " frame files for " + std::to_string(frames) + " frames");
  ok &= check(task_starts > 0 && boxed_task_starts == task_starts,
              "a box on every task start's frame");

  const cv::Mat sheet = cv::imread((dir / "feeds" / "contact_sheet.png").string());
  const auto grid = report::contact_sheet_layout::for_tiles(frames);
  ok &= check(!sheet.empty() && sheet.size() == grid.size(),
              "contact_sheet.png is the size of " + std::to_string(frames) + " tiles");
  for (std::size_t k = 0; ok && k < frames; ++k)
    ok &= check(test_support::shows_a_scene(test_support::statistics_of(sheet(grid.tile(k)))),
                "tile " + std::to_string(k) + " shows a scene");

  std::ifstream page(dir / "report.html");
  std::stringstream html;
  html << page.rdbuf();
  ok &= check(html.str().find("feeds/contact_sheet.png") != std::string::npos,
              "report.html shows the contact sheet");
  return ok ? 0 : 1;
}
