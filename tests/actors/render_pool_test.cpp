// The render pool renders exactly what a direct vision::renderer + imaging model renders,
// whichever worker serves; `run --video` writes one mosaic frame per tick, and each frame
// shows what the cameras see at that tick.

#include "actors/render_pool.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <set>

#include "actors/run_scenario.hpp"
#include "actors/system_config.hpp"
#include "actors/type_ids.hpp"
#include "config/scenario_loader.hpp"
#include "report/camera_logs.hpp"
#include "support/scene_checks.hpp"
#include "vision/capture.hpp"
#include "vision/feed_mosaic.hpp"
#include "vision/renderer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::actors {
namespace {

config::imaging_model degraded(int width, int height) {
  config::imaging_model m;
  m.width_px = static_cast<unsigned>(width);
  m.height_px = static_cast<unsigned>(height);
  m.color_response_enabled = true;
  m.response.hue_offset_deg = 4.0;
  m.noise_sigma = 4.0;
  m.dropout_fraction = 0.002;
  m.jpeg_quality = 75;
  return m;
}

TEST(render_pool, renders_the_same_bytes_as_a_direct_renderer_whichever_worker_serves) {
  auto scenario = config::load_scenario(ARGUS_SOURCE_DIR "/scenarios/penn_station.yaml");
  auto station = world::station::load(world::layout_path(scenario));
  auto settings = world::crowd_settings::from(scenario);
  settings.population = 40;
  world::crowd crowd(station, settings);
  const int width = 160;
  const int height = 120;
  std::vector<vision::camera_view> views;
  std::vector<vision::imaging_model> direct_models;
  std::vector<std::optional<vision::imaging_model>> pool_models;
  for (const auto& c : scenario.cameras) {
    views.push_back(
        {vision::camera_placement::from(c), vision::ptz_camera::from(c).state(), width, height});
    direct_models.push_back(
        vision::imaging_model::for_camera(degraded(width, height), scenario.run.seed, c.id));
    pool_models.push_back(direct_models.back());
  }
  vision::renderer direct(station);
  system_config cfg(2);
  caf::actor_system system{cfg};
  auto pool = spawn_render_pool(system, station, 2);
  std::set<std::size_t> workers;
  {
    caf::scoped_actor self{system};
    for (int tick = 0; tick < 3; ++tick) {
      crowd.step();
      auto frame = crowd.current();
      const double t = frame->time().count();
      // Every camera's request goes out before any answer is read: the pool renders them
      // concurrently, and each camera's noise still follows its own frames in tick order.
      std::vector<caf::response_handle<caf::blocking_actor, caf::message, true>> pending;
      for (std::size_t k = 0; k < views.size(); ++k) {
        render_request request{views[k], frame, t, 1.0 / 30.0, std::move(pool_models[k])};
        pending.push_back(self->request(pool.front, caf::infinite, render_atom_v, request));
      }
      for (std::size_t k = 0; k < views.size(); ++k) {
        cv::Mat expected = direct_models[k].apply(direct.render(views[k], *frame, t));
        pending[k].receive(
            [&](render_result& result) {
              workers.insert(result.worker);
              pool_models[k] = std::move(result.imaging);
              ASSERT_EQ(result.image.size(), expected.size());
              EXPECT_EQ(cv::norm(result.image, expected, cv::NORM_INF), 0.0)
                  << "camera " << scenario.cameras[k].id << " tick " << tick;
            },
            [&](caf::error& err) { FAIL() << system.render(err); });
      }
    }
  }
  EXPECT_EQ(workers, (std::set<std::size_t>{0, 1}));
  caf::anon_send_exit(pool.front, caf::exit_reason::user_shutdown);
}

// What a run's video is checked against: the scenario's cameras in the video's (id) order, its
// crowd stepped here, a renderer and the mosaic's layout at 160 x 120 tiles.
struct direct_scene {
  explicit direct_scene(const config::scenario& scenario)
      : cameras(by_id(scenario.cameras)),
        station(world::station::load(world::layout_path(scenario))),
        crowd(station, world::crowd_settings::from(scenario)),
        direct(station),
        layout(vision::feed_mosaic_layout::for_feeds(cameras.size(), 160, 120)) {}

  static std::vector<config::camera_settings> by_id(std::vector<config::camera_settings> c) {
    std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    return c;
  }

  std::vector<config::camera_settings> cameras;
  std::shared_ptr<const world::station> station;
  world::crowd crowd;
  vision::renderer direct;
  vision::feed_mosaic_layout layout;
};

// Runs `scenario` afresh with a video of 160 x 120 tiles.
run_outcome run_with_video(const config::scenario& scenario) {
  std::filesystem::remove_all(scenario.run.output_dir);
  run_options options;
  options.video = true;
  options.video_width_px = 160;
  options.video_height_px = 120;
  return run_scenario(scenario, options);
}

TEST(render_pool, run_with_video_writes_one_frame_per_tick) {
  auto scenario = config::load_scenario(ARGUS_SOURCE_DIR "/scenarios/penn_station.yaml");
  scenario.run.duration = std::chrono::duration<double>{2.0};
  scenario.run.threads = 2;
  scenario.run.output_dir = std::filesystem::temp_directory_path() / "argus_render_pool_test";
  const auto outcome = run_with_video(scenario);
  const auto file = outcome.output_dir / "video" / "feeds.avi";
  ASSERT_TRUE(std::filesystem::exists(file));
  EXPECT_FALSE(std::filesystem::exists(outcome.output_dir / "video" / "feeds.partial.avi"));
  cv::VideoCapture video(file.string());
  ASSERT_TRUE(video.isOpened());

  // What each frame must show: frame k is every camera's degraded view, at its default pose (no
  // task in the first 2 s, so no camera moves), of the crowd after k + 1 steps (the recorder's
  // snapshot of clock tick k), rendered here directly, each camera's imaging model applied to
  // its frames in tick order.
  direct_scene scene(scenario);
  const auto& cameras = scene.cameras;
  auto& crowd = scene.crowd;
  auto& direct = scene.direct;
  const auto& layout = scene.layout;
  std::vector<vision::camera_view> views;
  std::vector<vision::imaging_model> models;
  for (const auto& c : cameras) {
    views.push_back(
        {vision::camera_placement::from(c), vision::ptz_camera::from(c).state(), 160, 120});
    auto imaging = c.imaging;
    imaging.width_px = 160;
    imaging.height_px = 120;
    models.push_back(vision::imaging_model::for_camera(imaging, scenario.run.seed, c.id));
  }
  const double tick_s = scenario.run.tick.count();
  std::int64_t frames = 0;
  double worst_psnr_db = 1e9;
  cv::Mat image;
  while (video.read(image)) {
    ++frames;
    ASSERT_EQ(image.size(), layout.size());
    crowd.step();
    const auto& frame = *crowd.current();
    const double t = frame.time().count();
    for (std::size_t k = 0; k < cameras.size(); ++k) {
      cv::Mat expected = vision::capture(direct, views[k], frame, t, tick_s / 2.0, models[k]);
      vision::label_feed(expected, cameras[k].id);
      const cv::Mat tile = image(layout.tile(k));
      const auto seen = test_support::statistics_of(tile);
      EXPECT_TRUE(test_support::shows_a_scene(seen))
          << "frame " << frames << " camera " << cameras[k].id << ": mean " << seen.mean
          << ", stddev " << seen.stddev << ", lit " << seen.lit_fraction;
      // The tile is the view itself, up to the video's JPEG compression.
      const double psnr_db = cv::PSNR(tile, expected);
      worst_psnr_db = std::min(worst_psnr_db, psnr_db);
      EXPECT_GT(psnr_db, 25.0) << "frame " << frames << " camera " << cameras[k].id;
    }
  }
  std::printf("[ video    ] %lld frames; worst tile PSNR against a direct render %.1f dB\n",
              static_cast<long long>(frames), worst_psnr_db);
  EXPECT_EQ(frames, outcome.result.ticks);
  EXPECT_EQ(outcome.result.ticks, 30);
}

TEST(render_pool, run_with_video_shows_each_camera_at_its_pose) {
  // Seed 5, the task from 0 s: camera 7 takes a pedestrian at 1.9 s and turns and zooms after
  // her; every tile of every frame must show its camera's view at the pose its node saw that
  // tick with (poses.csv), not the default pose. Camera 1 is down from 1 s to 2 s: its tiles
  // then are its last view marked failed, and after it its own view again.
  auto scenario = config::load_scenario(ARGUS_SOURCE_DIR "/scenarios/penn_station.yaml");
  scenario.run.seed = 5;
  scenario.run.duration = std::chrono::duration<double>{3.0};
  scenario.tasks.at(0).at = config::seconds{0.0};
  config::fault crash;
  crash.at = config::seconds{1.0};
  crash.kind = config::fault_kind::crash_and_recover;
  crash.length = config::seconds{1.0};
  crash.camera = 1;
  scenario.faults.push_back(crash);
  scenario.run.threads = 2;
  scenario.run.output_dir = std::filesystem::temp_directory_path() / "argus_video_pose_test";
  // Raw frames, so that a tile can be compared with a render of any one frame (a camera's
  // noise depends on every frame before).
  for (auto& c : scenario.cameras) {
    config::imaging_model raw;
    raw.width_px = c.imaging.width_px;
    raw.height_px = c.imaging.height_px;
    c.imaging = raw;
  }
  const auto outcome = run_with_video(scenario);
  cv::VideoCapture video((outcome.output_dir / "video" / "feeds.avi").string());
  ASSERT_TRUE(video.isOpened());
  const auto poses = report::pose_history::read(outcome.output_dir / "poses.csv");

  direct_scene scene(scenario);
  const auto& cameras = scene.cameras;
  auto& crowd = scene.crowd;
  auto& direct = scene.direct;
  const auto& layout = scene.layout;
  std::int64_t frames = 0, moved = 0, failed = 0;
  double worst_psnr_db = 1e9;
  cv::Mat image;
  while (video.read(image)) {
    ++frames;
    crowd.step();
    const auto& frame = *crowd.current();
    for (std::size_t k = 0; k < cameras.size(); ++k) {
      vision::camera_view view{vision::camera_placement::from(cameras[k]),
                               vision::ptz_camera::from(cameras[k]).state(), 160, 120};
      const auto home = view.pose;
      const auto tick = static_cast<std::int64_t>(frame.tick());
      if (const auto* row = poses.at(cameras[k].id, tick))
        view.pose = {row->pan_deg, row->tilt_deg, row->field_of_view_deg};
      if (!(view.pose == home)) ++moved;
      cv::Mat expected = direct.render(view, frame, frame.time().count());
      // The recorder knows a node is down once it has missed a whole turn: a tick after the
      // first one poses.csv marks down.
      if (const auto* before = poses.at(cameras[k].id, tick - 1);
          before && before->state == "down") {
        vision::mark_failed_feed(expected);
        ++failed;
      }
      vision::label_feed(expected, cameras[k].id);
      const double psnr_db = cv::PSNR(image(layout.tile(k)), expected);
      worst_psnr_db = std::min(worst_psnr_db, psnr_db);
      EXPECT_GT(psnr_db, 25.0) << "frame " << frames << " camera " << cameras[k].id;
    }
  }
  std::printf(
      "[ video    ] %lld tiles of a moved camera, %lld of a failed one; worst tile PSNR "
      "%.1f dB\n",
      static_cast<long long>(moved), static_cast<long long>(failed), worst_psnr_db);
  EXPECT_EQ(frames, outcome.result.ticks);
  EXPECT_GT(moved, 10);
  EXPECT_GT(failed, 10);
}

}  // namespace
}  // namespace argus::actors
