// Tracking accuracy on rendered sequences with ground truth (issue #5).
//
// For every (crowd density, noise level) cell, one crowd sequence of penn_station is stepped
// at the scenario's tick and a few cameras each follow one pedestrian with the pixel pipeline
// exactly as a camera node does in PerformingTask:
//
//   render (llvmpipe) --> imaging model --> tracker (backprojection + multiscale localiser)
//        ^                                        |
//        +------ pose <-- tracking_fsm (Track: fixate and zoom / Wait / Search) <--+
//
// Set-up per camera: from its default pose, the visible pedestrian nearest the image centre
// (unoccluded, at least 20 px tall) is chosen; the camera starts at the centring pose that
// makes it half the frame high, and the tracker starts on its ground-truth box there, its
// signature taken from that first (degraded) frame inside the box (or, with --signature
// appearance, from the pedestrian's clean appearance). Each later frame, ground truth
// (visible_pedestrians: projected boxes, clipped to the frame: the visible boxes) classifies
// the tracker's box B:
//
//   held    IoU(B, the target's visible box) >= 0.5;
//   other   B covers another pedestrian more than the target (a larger fraction of that
//           pedestrian's visible box lies inside B than of the target's): wrong identity;
//   astray  neither: B on the floor, on a part of the target, or far larger than it;
//   lost    the tracker reported the target lost (Wait / Search / failed);
//   switch  a frame "other" whose last classified frame was "held" (an identity switch).
//
// `centre` is the older, looser score, shown beside it: B contains the target's body centre,
// however large B is.
//
// Frames are counted while the target is in the station (it may leave by a portal).
// Densities and noise levels share the seed, so every cell follows the same people.
//
// Usage: tracking_bench [--seconds S] [--cameras N] [--width PX --height PX]
//                       [--signature first_frame|appearance] [--json FILE] [--scenario FILE]
//                       [--scales target|paper]  (the tracker's kernel sizes; target by default)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "config/scenario_loader.hpp"
#include "config/ticks.hpp"
#include "fmt/format.h"
#include "vision/capture.hpp"
#include "vision/color_histogram.hpp"
#include "vision/emulated_sensor.hpp"
#include "vision/fixate_zoom.hpp"
#include "vision/imaging_model.hpp"
#include "vision/ptz_camera.hpp"
#include "vision/renderer.hpp"
#include "vision/tracker.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace {

using namespace argus;

struct density {
  const char* name;
  unsigned population;
  double spawn_rate_per_min;
};

struct noise_level {
  const char* name;
  config::imaging_model imaging;
};

// penn_station's own crowd is 100 people arriving at 30 a minute (the "default" row).
constexpr density densities[] = {
    {"sparse", 40, 12.0}, {"default", 100, 30.0}, {"dense", 300, 90.0}};

std::vector<noise_level> noise_levels(unsigned width_px, unsigned height_px) {
  config::imaging_model none;
  none.width_px = width_px;
  none.height_px = height_px;
  // A cheap surveillance camera: mild detector noise, interlacing, JPEG at 75.
  auto moderate = none;
  moderate.noise_sigma = 8.0;
  moderate.jpeg_quality = 75;
  moderate.interlace = true;
  // A bad one: strong noise, 5 % salt-and-pepper dropout, JPEG at 30, a colour cast.
  auto heavy = moderate;
  heavy.noise_sigma = 25.0;
  heavy.dropout_fraction = 0.05;
  heavy.dropout = config::dropout_kind::salt_and_pepper;
  heavy.jpeg_quality = 30;
  heavy.color_response_enabled = true;
  heavy.response.hue_offset_deg = 10.0;
  heavy.response.saturation_gain = 0.8;
  heavy.response.tint = 0.1;
  return {{"none", none}, {"moderate", moderate}, {"heavy", heavy}};
}

struct target_counts {
  int frames = 0;
  int held = 0;
  int centre = 0;
  int other = 0;
  int astray = 0;
  int lost = 0;
  int switches = 0;
  int in_view = 0;
};

// One camera following one pedestrian.
struct follower {
  const config::camera_settings* camera;
  int target_id = -1;
  vision::ptz_state pose;
  vision::imaging_model imaging;
  std::optional<vision::tracker> track;
  std::optional<vision::tracking_fsm> fsm;
  // Last classified frame held the target (true) or another pedestrian (false).
  std::optional<bool> last_on_target;
  target_counts counts;
};

vision::camera_view view_of(const follower& f, int width_px, int height_px) {
  return {vision::camera_placement::from(*f.camera), f.pose, width_px, height_px};
}

cv::Point2d centre_of(const cv::Rect2d& box) {
  return {box.x + box.width / 2.0, box.y + box.height / 2.0};
}

cv::Mat capture(vision::renderer& render, follower& f, const world::snapshot& frame, int tick,
                double tick_s, int width_px, int height_px) {
  const auto view = view_of(f, width_px, height_px);
  return vision::capture(render, view, frame, tick * tick_s, tick_s / 2.0, f.imaging);
}

// Chooses the target and the zoomed starting pose; false when the camera sees nobody usable.
bool choose_target(follower& f, const world::snapshot& frame, const world::station& where,
                   int width_px, int height_px) {
  const cv::Point2d image_centre(width_px / 2.0, height_px / 2.0);
  const cv::Rect2d image(0.0, 0.0, width_px, height_px);
  const vision::frame_size size{width_px, height_px};
  std::vector<vision::pedestrian_view> candidates;
  for (const auto& seen :
       vision::visible_pedestrians(frame, where, view_of(f, width_px, height_px)))
    if (seen.occlusion < 0.05 && seen.box.height >= 20.0 && (seen.box & image) == seen.box)
      candidates.push_back(seen);
  std::sort(candidates.begin(), candidates.end(), [&](const auto& a, const auto& b) {
    return cv::norm(centre_of(a.box) - image_centre) < cv::norm(centre_of(b.box) - image_centre);
  });
  const auto limits = vision::ptz_limits::from(*f.camera);
  for (const auto& candidate : candidates) {
    const auto zoomed = limits.clamp(vision::centring_pose(f.pose, candidate.box, size, 0.5));
    follower trial = f;
    trial.pose = zoomed;
    // In the zoomed view the target must still be in sight and hardly occluded.
    for (const auto& seen :
         vision::visible_pedestrians(frame, where, view_of(trial, width_px, height_px)))
      if (seen.id == candidate.id && seen.occlusion < 0.2) {
        f.pose = zoomed;
        f.target_id = candidate.id;
        return true;
      }
  }
  return false;
}

double intersection_over_union(const cv::Rect2d& a, const cv::Rect2d& b) {
  const double common = (a & b).area();
  const double either = a.area() + b.area() - common;
  return either > 0.0 ? common / either : 0.0;
}

// The fraction of `covered` inside `box`.
double coverage(const cv::Rect2d& box, const cv::Rect2d& covered) {
  return covered.area() > 0.0 ? (box & covered).area() / covered.area() : 0.0;
}

// Classifies one frame of `f` against ground truth.
void score_frame(follower& f, const vision::track_observation& seen, const world::snapshot& frame,
                 const world::station& where, int width_px, int height_px) {
  auto& c = f.counts;
  ++c.frames;
  const auto people = vision::visible_pedestrians(frame, where, view_of(f, width_px, height_px));
  for (const auto& p : people)
    if (p.id == f.target_id && p.occlusion < 1.0) ++c.in_view;
  if (!seen.found) {
    ++c.lost;
    return;
  }
  const cv::Rect2d box(seen.box);
  const cv::Rect2d image(0.0, 0.0, width_px, height_px);
  double target_iou = 0.0, target_cover = 0.0, other_cover = 0.0;
  for (const auto& p : people) {
    const auto visible = p.box & image;
    if (p.id == f.target_id) {
      target_iou = intersection_over_union(box, visible);
      target_cover = coverage(box, visible);
      if (box.contains(centre_of(p.box))) ++c.centre;
    } else if (p.occlusion < 1.0) {
      other_cover = std::max(other_cover, coverage(box, visible));
    }
  }
  if (target_iou >= 0.5) {
    ++c.held;
    f.last_on_target = true;
  } else if (other_cover > target_cover) {
    ++c.other;
    if (f.last_on_target == true) ++c.switches;
    f.last_on_target = false;
  } else {
    ++c.astray;
  }
}

// Where the tracker's target signature comes from.
enum class signature_source {
  // The first degraded frame, inside the ground-truth box: what a node would capture.
  first_frame,
  // The pedestrian's clean appearance (appearance_signature), as the calibration uses.
  appearance
};

// The central part of a pedestrian's box (half its width, 90 % of its height): the whole box
// is mostly floor beside a thin body, and a signature full of floor colours makes the
// backprojection light up the floor and the localiser pick its largest kernel.
cv::Rect inner_part(const cv::Rect& box) {
  return {box.x + box.width / 4, box.y + box.height / 20, std::max(box.width / 2, 1),
          std::max(box.height * 9 / 10, 1)};
}

struct cell_result {
  std::string density;
  std::string noise;
  std::vector<target_counts> targets;
  double wall_s = 0.0;
};

cell_result run_cell(const config::scenario& scenario, std::shared_ptr<const world::station> where,
                     vision::renderer& render, const density& d, const noise_level& n,
                     double seconds, std::size_t cameras, signature_source signature,
                     const vision::tracker_settings& tracking) {
  const auto started = std::chrono::steady_clock::now();
  auto settings = world::crowd_settings::from(scenario);
  settings.population = d.population;
  settings.spawn_rate_per_min = d.spawn_rate_per_min;
  world::crowd crowd(where, settings);
  const int width = static_cast<int>(n.imaging.width_px);
  const int height = static_cast<int>(n.imaging.height_px);
  const double tick_s = scenario.run.tick.count();
  const config::seconds dt{tick_s};

  std::vector<follower> followers;
  for (const auto& camera : scenario.cameras) {
    if (followers.size() == cameras) break;
    follower f{&camera,
               -1,
               vision::ptz_camera::from(camera).state(),
               vision::imaging_model::for_camera(n.imaging, scenario.run.seed, camera.id),
               {},
               {},
               {},
               {}};
    if (!choose_target(f, *crowd.current(), *where, width, height)) continue;
    followers.push_back(std::move(f));
  }
  // Tick 0: the first frame starts every track on the ground-truth box.
  for (auto& f : followers) {
    const auto image = capture(render, f, *crowd.current(), 0, tick_s, width, height);
    for (const auto& p :
         vision::visible_pedestrians(*crowd.current(), *where, view_of(f, width, height)))
      if (p.id == f.target_id) {
        const cv::Rect box = cv::Rect(p.box) & cv::Rect(0, 0, width, height);
        f.track.emplace(signature == signature_source::first_frame
                            ? vision::color_histogram::of_region(image, inner_part(box))
                            : vision::appearance_signature(crowd.current()->find(p.id)->look),
                        tracking);
        f.track->start(box);
        f.fsm.emplace(vision::ptz_limits::from(*f.camera), scenario.controller);
      }
  }
  const auto ticks = config::to_ticks(config::seconds{seconds}, config::seconds{tick_s});
  for (int tick = 1; tick <= ticks; ++tick) {
    crowd.step();
    const auto& frame = *crowd.current();
    for (auto& f : followers) {
      if (!f.track || frame.find(f.target_id) == nullptr) continue;
      vision::track_observation seen{false, f.track->box().value_or(cv::Rect{}), 0.0};
      if (f.fsm->state() != vision::tracking_state::failed)
        seen = f.track->update(capture(render, f, frame, tick, tick_s, width, height));
      score_frame(f, seen, frame, *where, width, height);
      f.pose = f.fsm->step(seen, f.pose, {width, height}, dt).pose;
    }
  }
  cell_result result{d.name, n.name, {}, 0.0};
  for (const auto& f : followers)
    if (f.track) result.targets.push_back(f.counts);
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

target_counts total_of(const cell_result& cell) {
  target_counts t;
  for (const auto& c : cell.targets) {
    t.frames += c.frames;
    t.held += c.held;
    t.centre += c.centre;
    t.other += c.other;
    t.astray += c.astray;
    t.lost += c.lost;
    t.switches += c.switches;
    t.in_view += c.in_view;
  }
  return t;
}

double fraction(int part, int whole) {
  return whole > 0 ? static_cast<double>(part) / whole : 0.0;
}

std::string to_json(const std::vector<cell_result>& cells, double seconds, int width, int height,
                    signature_source signature) {
  std::string out = fmt::format(
      "{{\"scenario\": \"penn_station\", \"seconds\": {}, \"width_px\": {}, \"height_px\": {}, "
      "\"signature\": \"{}\", \"cells\": [",
      seconds, width, height,
      signature == signature_source::first_frame ? "first_frame" : "appearance");
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const auto& cell = cells[i];
    const auto t = total_of(cell);
    out += fmt::format(
        "{}\n  {{\"density\": \"{}\", \"noise\": \"{}\", \"targets\": {}, \"frames\": {}, "
        "\"held\": {}, \"centre\": {}, \"other\": {}, \"astray\": {}, \"lost\": {}, \"switches\": "
        "{}, \"in_view\": "
        "{}, "
        "\"held_fraction\": {:.4f}, \"wall_s\": {:.2f}, \"per_target_held\": [",
        i == 0 ? "" : ",", cell.density, cell.noise, cell.targets.size(), t.frames, t.held,
        t.centre, t.other, t.astray, t.lost, t.switches, t.in_view, fraction(t.held, t.frames),
        cell.wall_s);
    for (std::size_t k = 0; k < cell.targets.size(); ++k)
      out += fmt::format("{}{:.4f}", k == 0 ? "" : ", ",
                         fraction(cell.targets[k].held, cell.targets[k].frames));
    out += "]}";
  }
  out += "\n]}\n";
  return out;
}

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr,
               "tracking_bench: %s\nusage: tracking_bench [--seconds S] [--cameras N] "
               "[--width PX --height PX] [--signature first_frame|appearance] [--json FILE] "
               "[--scales target|paper] "
               "[--scenario FILE]\n",
               why.c_str());
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 20.0;
  std::size_t cameras = 8;
  int width = 320, height = 240;
  std::string json_path = "tracking_bench.json";
  signature_source signature = signature_source::first_frame;
  vision::tracker_settings tracking;
  std::string scenario_path = ARGUS_SOURCE_DIR "/scenarios/penn_station.yaml";
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (i + 1 >= argc) usage(fmt::format("{} needs a value", flag));
    const std::string value = argv[++i];
    try {
      if (flag == "--seconds")
        seconds = std::stod(value);
      else if (flag == "--cameras")
        cameras = static_cast<std::size_t>(std::stoul(value));
      else if (flag == "--width")
        width = std::stoi(value);
      else if (flag == "--height")
        height = std::stoi(value);
      else if (flag == "--json")
        json_path = value;
      else if (flag == "--signature" && value == "first_frame")
        signature = signature_source::first_frame;
      else if (flag == "--signature" && value == "appearance")
        signature = signature_source::appearance;
      else if (flag == "--signature")
        usage(fmt::format("--signature is first_frame or appearance, not {}", value));
      else if (flag == "--scenario")
        scenario_path = value;
      else if (flag == "--scales" && (value == "target" || value == "paper"))
        tracking.scales.rule =
            value == "paper" ? vision::scale_rule::paper : vision::scale_rule::target;
      else if (flag == "--scales")
        usage(fmt::format("--scales is target or paper, not {}", value));
      else
        usage(fmt::format("unknown option {}", flag));
    } catch (const std::logic_error&) {
      usage(fmt::format("{}: not a number: {}", flag, value));
    }
  }
  if (seconds <= 0.0 || cameras == 0 || width < 16 || height < 16)
    usage("--seconds, --cameras must be positive and the frame at least 16 x 16");

  config::scenario scenario;
  std::shared_ptr<const world::station> where;
  try {
    scenario = config::load_scenario(scenario_path);
    where = world::station::load(world::layout_path(scenario));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tracking_bench: %s\n", e.what());
    return 2;
  }
  vision::renderer render(where);
  std::vector<cell_result> cells;
  // Fractions of the frames in which the target is in the station.
  std::printf("%-8s %-9s %7s %7s %7s %7s %7s %7s %7s %8s %8s %6s\n", "density", "noise", "targets",
              "frames", "held", "centre", "other", "astray", "lost", "switches", "in_view",
              "wall_s");
  for (const auto& d : densities)
    for (const auto& n : noise_levels(width, height)) {
      cells.push_back(
          run_cell(scenario, where, render, d, n, seconds, cameras, signature, tracking));
      const auto t = total_of(cells.back());
      std::printf("%-8s %-9s %7zu %7d %7.3f %7.3f %7.3f %7.3f %7.3f %8d %8.3f %6.1f\n", d.name,
                  n.name, cells.back().targets.size(), t.frames, fraction(t.held, t.frames),
                  fraction(t.centre, t.frames), fraction(t.other, t.frames),
                  fraction(t.astray, t.frames), fraction(t.lost, t.frames), t.switches,
                  fraction(t.in_view, t.frames), cells.back().wall_s);
      std::fflush(stdout);
    }
  std::ofstream(json_path) << to_json(cells, seconds, width, height, signature);
  std::printf("wrote %s\n", json_path.c_str());
}
