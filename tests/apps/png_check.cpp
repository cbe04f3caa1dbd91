// Decodes a PNG that `argus` wrote and checks what it must show; exit 0 when it does.
//   png_check plan PNG SCENARIO TIME_S TRAILS_S   walls, cameras, pedestrians and trails where
//                                                 the scenario's crowd puts them at TIME_S
//   png_check frame PNG WIDTH HEIGHT              one camera's view: that size, not blank
//   png_check mosaic PNG TILE_W TILE_H TILES      every tile of a feed mosaic not blank
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "config/scenario_loader.hpp"
#include "config/ticks.hpp"
#include "support/scene_checks.hpp"
#include "vision/feed_mosaic.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/plan_view_checks.hpp"
#include "world/trajectory_writer.hpp"

namespace {

using namespace argus;

bool check(bool ok, const std::string& what) {
  std::printf("%s %s\n", ok ? "ok:  " : "FAIL:", what.c_str());
  return ok;
}

bool not_blank(const cv::Mat& picture, const std::string& name) {
  const auto s = test_support::statistics_of(picture);
  return check(test_support::shows_a_scene(s),
               name + " shows a scene (mean " + std::to_string(s.mean) + ", stddev " +
                   std::to_string(s.stddev) + ", lit " + std::to_string(s.lit_fraction) + ")");
}

// The plan view of `argus plan SCENARIO --time TIME_S --trails TRAILS_S`, checked against the
// crowd stepped here to the same tick.
bool check_plan(const cv::Mat& image, const std::string& file, double time_s, double trails_s) {
  const auto scenario = config::load_scenario(file);
  const auto station = world::station::load(world::layout_path(scenario));
  world::crowd crowd(station, world::crowd_settings::from(scenario));
  world::trail_recorder trails(std::chrono::duration<double>{trails_s});
  trails.record(*crowd.current());
  const auto ticks = config::to_ticks(config::seconds{time_s}, scenario.run.tick);
  for (std::int64_t k = 0; k < ticks; ++k) {
    crowd.step();
    trails.record(*crowd.current());
  }
  const auto f = world::inspect_plan_view(image, *station, scenario.cameras, *crowd.current(),
                                          trails.trails());
  f.print();
  bool ok = check(f.walls > 300 && f.walls_drawn >= f.walls * 8 / 10, "walls drawn");
  ok &= check(f.cameras > 0 && f.cameras_drawn >= f.cameras - 1, "cameras drawn");
  ok &= check(f.pedestrians > 20 && f.pedestrians_drawn >= f.pedestrians * 9 / 10,
              "pedestrians drawn");
  ok &= check(f.trails > 10 && f.trails_drawn * 3 >= f.trails * 2, "trails drawn");
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() < 2) return 2;
  const cv::Mat image = cv::imread(args[1], cv::IMREAD_COLOR);
  if (!check(!image.empty(), "decodes " + args[1])) return 1;
  bool ok = false;
  if (args[0] == "plan" && args.size() == 5) {
    ok = check_plan(image, args[2], std::stod(args[3]), std::stod(args[4]));
  } else if (args[0] == "frame" && args.size() == 4) {
    ok = check(image.cols == std::stoi(args[2]) && image.rows == std::stoi(args[3]),
               "size " + std::to_string(image.cols) + "x" + std::to_string(image.rows));
    ok &= not_blank(image, "the frame");
  } else if (args[0] == "mosaic" && args.size() == 5) {
    const auto layout = vision::feed_mosaic_layout::for_feeds(
        std::stoul(args[4]), std::stoi(args[2]), std::stoi(args[3]));
    ok = check(image.size() == layout.size(), "mosaic size");
    for (std::size_t k = 0; ok && k < std::stoul(args[4]); ++k)
      ok &= not_blank(image(layout.tile(k)), "tile " + std::to_string(k));
  } else {
    std::fprintf(stderr, "png_check: unknown check\n");
    return 2;
  }
  return ok ? 0 : 1;
}
