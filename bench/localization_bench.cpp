// Finding a person again by colour (issue 19): a patch of a person cut from one frame, the
// same person searched for in the whole frame 5, 15 or 30 frames later. A search hits when its
// first box overlaps the person's true box by IoU >= 0.3. Methods:
//
//   default   Fig. 9's multiscale localiser at kernel sizes around the patch's size
//             (vision::kernel_scales, half to twice it), rho 0.5 (`argus vision localize`)
//   paper     the same at the paper's scales, (0.1 ... 1) x frame height / 7 (--scales paper)
//   single    Swain and Ballard's single scale, the kernel sized to the patch
//   camshift  OpenCV's CamShift on the patch's hue histogram (as in OpenCV's camshift
//             sample: 16 bins, saturation >= 30, value >= 10), started at the patch's box
//
// Two sets of searches:
//
//   real      tests/data/vtest: frames of OpenCV's vtest.avi (768x576, 10 frames/s), boxes
//             checked by hand (tests/support/real_video_searches.hpp)
//   rendered  penn_station, its 16 cameras held at their default poses ("default zoom") or
//             all at a 20 degree field of view ("tracking zoom"), 320x240; every pedestrian
//             visible, at most 30 % occluded and at least 12 px tall in both frames, cut from
//             its projected box at t and searched at t + 5, 15, 30 ticks (1/15 s), t = 30,
//             45, ..., 120 s
//
// Time per search: colour indexing and localisation (CamShift: its backprojection and
// iterations), in-process, the median over the searches.
//
// Usage: localization_bench [--data DIR] [--scenario FILE] [--real-only]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/scenario_loader.hpp"
#include "config/ticks.hpp"
#include "fmt/format.h"
#include "opencv2/imgproc.hpp"
#include "opencv2/video/tracking.hpp"
#include "tests/support/real_video_searches.hpp"
#include "vision/emulated_sensor.hpp"
#include "vision/imaging_model.hpp"
#include "vision/kernel_scales.hpp"
#include "vision/patch_search.hpp"
#include "vision/renderer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace {

using namespace argus;
using test_support::overlap;

// One search: the patch's frame and box, the frame searched and the true box there.
struct search {
  const cv::Mat* from = nullptr;
  const cv::Mat* to = nullptr;
  cv::Rect patch_box;
  cv::Rect truth;
  int interval = 0;
};

using method = std::function<std::optional<cv::Rect>(const search&)>;

std::optional<cv::Rect> first_box(const std::vector<vision::localized_region>& found) {
  if (found.empty()) return std::nullopt;
  return found.front().box();
}

std::optional<cv::Rect> with_scales(const search& s, vision::scale_rule rule) {
  vision::scale_settings settings;
  settings.rule = rule;
  return first_box(
      vision::find_patch(*s.to, (*s.from)(s.patch_box),
                         vision::localizer_settings_for(settings, cv::Size2d(s.patch_box.size()),
                                                        s.to->rows, 0.5, 1)));
}

std::optional<cv::Rect> single_scale(const search& s) {
  const int l = std::max(
      1, static_cast<int>(std::lround(vision::kernel_size_for(cv::Size2d(s.patch_box.size())))));
  return first_box(vision::find_patch(*s.to, (*s.from)(s.patch_box), {{l}, 0.5, 1}));
}

// OpenCV's samples/cpp/camshiftdemo.cpp, without its interactive parts.
std::optional<cv::Rect> camshift(const search& s) {
  const int bins = 16;
  const float range[] = {0.0f, 180.0f};
  const float* ranges[] = {range};
  const int channels[] = {0};
  auto hue_and_mask = [](const cv::Mat& bgr, cv::Mat& hue, cv::Mat& mask) {
    cv::Mat hsv;
    cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
    cv::inRange(hsv, cv::Scalar(0, 30, 10), cv::Scalar(180, 256, 256), mask);
    cv::extractChannel(hsv, hue, 0);
  };
  cv::Mat hue, mask, histogram;
  hue_and_mask((*s.from)(s.patch_box), hue, mask);
  cv::calcHist(&hue, 1, channels, mask, histogram, 1, &bins, ranges);
  cv::normalize(histogram, histogram, 0, 255, cv::NORM_MINMAX);
  hue_and_mask(*s.to, hue, mask);
  cv::Mat back;
  cv::calcBackProject(&hue, 1, channels, histogram, back, ranges);
  back &= mask;
  cv::Rect window = s.patch_box;
  const auto box = cv::CamShift(
      back, window, cv::TermCriteria(cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 10, 1));
  const cv::Rect found = box.boundingRect() & cv::Rect(0, 0, s.to->cols, s.to->rows);
  if (found.empty()) return std::nullopt;
  return found;
}

struct method_entry {
  std::string name;
  method find;
};

std::vector<method_entry> methods() {
  return {{"default (target scales)",
           [](const search& s) { return with_scales(s, vision::scale_rule::target); }},
          {"paper scales (h / 7)",
           [](const search& s) { return with_scales(s, vision::scale_rule::paper); }},
          {"single scale, patch-sized", single_scale},
          {"OpenCV CamShift", camshift}};
}

// Hit rates per interval and overall, median time per search, as a Markdown table.
void report(const std::string& title, const std::vector<search>& searches) {
  const std::vector<int> intervals{5, 15, 30};
  fmt::print("\n{} ({} searches)\n\n", title, searches.size());
  fmt::print("| method |");
  for (const int i : intervals) {
    int n = 0;
    for (const auto& s : searches) n += s.interval == i ? 1 : 0;
    fmt::print(" {} apart (n={}) |", i, n);
  }
  fmt::print(" all | ms per search |\n| --- |");
  for (std::size_t i = 0; i < intervals.size() + 2; ++i) fmt::print(" ---: |");
  fmt::print("\n");
  for (const auto& m : methods()) {
    std::map<int, int> hits, counts;
    std::vector<double> ms;
    int all = 0;
    for (const auto& s : searches) {
      const auto start = std::chrono::steady_clock::now();
      const auto found = m.find(s);
      ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count());
      const bool hit = found && overlap(*found, s.truth) >= 0.3;
      hits[s.interval] += hit ? 1 : 0;
      counts[s.interval] += 1;
      all += hit ? 1 : 0;
    }
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    fmt::print("| {} |", m.name);
    for (const int i : intervals)
      fmt::print(" {:.2f} |", counts[i] > 0 ? static_cast<double>(hits[i]) / counts[i] : 0.0);
    fmt::print(" **{:.2f}** | {:.2f} |\n",
               searches.empty() ? 0.0 : static_cast<double>(all) / searches.size(),
               ms.empty() ? 0.0 : ms[ms.size() / 2]);
  }
}

void real_video(const std::string& directory) {
  const auto set = test_support::load_real_video_set(directory);
  std::vector<search> searches;
  for (const auto& s : set.searches)
    searches.push_back(
        {&set.frames.at(s.from), &set.frames.at(s.to), s.patch_box, s.truth, s.interval()});
  const auto& frame = set.frames.begin()->second;
  report(fmt::format("Real video: {} ({}x{})", directory, frame.cols, frame.rows), searches);
}

// The rendered station at one zoom: frames of every camera at t and t + interval.
void rendered(const std::string& scenario_file, std::optional<double> field_of_view_deg,
              const std::string& title) {
  auto scenario = config::load_scenario(scenario_file);
  const auto station = world::station::load(world::layout_path(scenario));
  world::crowd crowd(station, world::crowd_settings::from(scenario));
  vision::renderer renderer(station);
  const double tick_s = scenario.run.tick.count();
  const int width = 320, height = 240;
  std::vector<vision::camera_view> views;
  std::vector<vision::imaging_model> imaging;
  for (const auto& c : scenario.cameras) {
    config::imaging_model settings = c.imaging;
    settings.width_px = width;
    settings.height_px = height;
    auto pose = vision::ptz_camera::from(c).state();
    if (field_of_view_deg) pose.field_of_view_deg = *field_of_view_deg;
    views.push_back({vision::camera_placement::from(c), pose, width, height});
    imaging.push_back(vision::imaging_model::for_camera(settings, scenario.run.seed, c.id));
  }
  const std::vector<int> intervals{5, 15, 30};
  std::vector<std::int64_t> starts;
  for (double t = 30.0; t <= 120.0; t += 15.0)
    starts.push_back(config::to_ticks(config::seconds{t}, scenario.run.tick));
  // Frames kept per (tick, camera), with the boxes of the pedestrians usable there.
  struct shot {
    cv::Mat image;
    std::map<int, cv::Rect> boxes;
  };
  std::map<std::pair<std::int64_t, std::size_t>, shot> shots;
  std::vector<std::int64_t> wanted;
  for (const auto t : starts) {
    wanted.push_back(t);
    for (const int i : intervals) wanted.push_back(t + i);
  }
  std::sort(wanted.begin(), wanted.end());
  const cv::Rect image_rect(0, 0, width, height);
  for (std::int64_t tick = 0; tick <= wanted.back(); ++tick) {
    if (tick > 0) crowd.step();
    if (!std::binary_search(wanted.begin(), wanted.end(), tick)) continue;
    const auto& frame = *crowd.current();
    for (std::size_t c = 0; c < views.size(); ++c) {
      shot s;
      s.image = imaging[c].apply(renderer.render(views[c], frame, tick * tick_s));
      for (const auto& v : vision::visible_pedestrians(frame, *station, views[c])) {
        const cv::Rect box = cv::Rect(v.box) & image_rect;
        if (v.occlusion <= 0.3 && box.height >= 12 && box.width >= 3) s.boxes[v.id] = box;
      }
      shots[{tick, c}] = std::move(s);
    }
  }
  std::vector<search> searches;
  for (const auto t : starts)
    for (const int i : intervals)
      for (std::size_t c = 0; c < views.size(); ++c) {
        const auto& a = shots.at({t, c});
        const auto& b = shots.at({t + i, c});
        for (const auto& [id, box] : a.boxes) {
          const auto later = b.boxes.find(id);
          if (later != b.boxes.end())
            searches.push_back({&a.image, &b.image, box, later->second, i});
        }
      }
  report(title, searches);
}

}  // namespace

int main(int argc, char** argv) {
  std::string data = ARGUS_SOURCE_DIR "/tests/data/vtest";
  std::string scenario = ARGUS_SOURCE_DIR "/scenarios/penn_station.yaml";
  bool real_only = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--data" && i + 1 < argc) {
      data = argv[++i];
    } else if (arg == "--scenario" && i + 1 < argc) {
      scenario = argv[++i];
    } else if (arg == "--real-only") {
      real_only = true;
    } else {
      std::fprintf(stderr,
                   "usage: localization_bench [--data DIR] [--scenario FILE] [--real-only]\n");
      return 2;
    }
  }
  real_video(data);
  if (real_only) return 0;
  rendered(scenario, std::nullopt, "Rendered station, default zoom (320x240)");
  rendered(scenario, 20.0, "Rendered station, tracking zoom (20 deg, 320x240)");
  return 0;
}
