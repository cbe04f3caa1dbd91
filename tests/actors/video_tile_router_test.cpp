// A distributed run's video tiles (docs/distributed.md, "Video"): each camera's is rendered by
// the worker that hosts it, crosses as the imaging model's JPEG bytes or as raw rows, and is the
// same to the byte as one rendered here, its noise carried on from tick to tick; a lost worker's
// tiles, in flight or later, are rendered here with the same bytes again. The worker hosts here are
// stand-ins that render as `argus worker` does, with the same conversions (actors/video_tiles.hpp);
// distributed_test runs the real ones.

#include "actors/video_tile_router.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <opencv2/core.hpp>
#include <thread>

#include "actors/render_pool.hpp"
#include "actors/system_config.hpp"
#include "actors/type_ids.hpp"
#include "actors/video_tiles.hpp"
#include "config/scenario_loader.hpp"
#include "vision/renderer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::actors {
namespace {

constexpr video_tile_settings tiles{96, 72, true};

struct stand_in_state {
  config::scenario scenario;
  std::shared_ptr<const world::station> station;
  std::unique_ptr<vision::renderer> renderer;
  std::shared_ptr<const world::snapshot> board;
  /// Tiles rendered, and tiles taken but never answered (`hold`).
  std::shared_ptr<std::atomic<int>> served;
  std::shared_ptr<std::atomic<int>> held;
  bool hold = false;
  std::vector<caf::response_promise> kept;
};

// A worker host as far as the video goes: its board holds `board` (set by `(board_atom, ...)`).
caf::behavior stand_in(caf::stateful_actor<stand_in_state>* self, config::scenario scenario,
                       std::shared_ptr<const world::station> station,
                       std::shared_ptr<std::atomic<int>> served,
                       std::shared_ptr<std::atomic<int>> held, bool hold) {
  auto& st = self->state;
  st.scenario = std::move(scenario);
  st.renderer = std::make_unique<vision::renderer>(station);
  st.station = std::move(station);
  st.served = std::move(served);
  st.held = std::move(held);
  st.hold = hold;
  return {
      [self](board_atom, std::shared_ptr<const world::snapshot>& frame) {
        self->state.board = std::move(frame);
      },
      [self](video_tile_atom, const video_tile_request& tile) -> caf::result<video_tile> {
        auto& st = self->state;
        if (st.hold) {
          st.kept.push_back(self->make_response_promise());
          ++*st.held;
          return caf::delegated<video_tile>{};
        }
        for (const auto& c : st.scenario.cameras)
          if (c.id == tile.camera) {
            auto request = from_tile_request(tile, c, tiles, st.board,
                                             video_imaging_model(c, tiles, st.scenario.run.seed));
            ++*st.served;
            return to_tile(render_frame(*st.renderer, std::move(request)));
          }
        return caf::make_error(caf::sec::runtime_error, "no such camera");
      },
  };
}

struct scene {
  scene()
      : scenario(config::load_scenario(ARGUS_SOURCE_DIR "/scenarios/penn_station.yaml")),
        station(world::station::load(world::layout_path(scenario))),
        crowd(station,
              [&] {
                auto s = world::crowd_settings::from(scenario);
                s.population = 40;
                return s;
              }()),
        direct(station) {
    for (const auto& c : scenario.cameras) {
      direct_models.emplace(c.id, video_imaging_model(c, tiles, scenario.run.seed));
      models.emplace(c.id, direct_models.at(c.id));
    }
  }

  // Camera `id`'s tile of `frame` at its default pose, without an imaging model.
  render_request bare(int id, const std::shared_ptr<const world::snapshot>& frame) const {
    const auto& c = camera(id);
    render_request r;
    r.camera = id;
    r.view = {vision::camera_placement::from(c), vision::ptz_camera::from(c).state(),
              tiles.width_px, tiles.height_px};
    r.frame = frame;
    r.time_s = frame->time().count();
    r.field_interval_s = scenario.run.tick.count() / 2.0;
    return r;
  }

  // Camera `id`'s request for `frame`, with its imaging model as the recorder keeps it.
  render_request request(int id, const std::shared_ptr<const world::snapshot>& frame) {
    auto r = bare(id, frame);
    r.imaging = std::move(models.at(id));
    models.erase(id);
    return r;
  }

  // What camera `id`'s tile of `frame` must be, rendered here with its noise in tick order.
  cv::Mat expected(int id, const std::shared_ptr<const world::snapshot>& frame) {
    auto r = bare(id, frame);
    r.imaging = std::move(direct_models.at(id));
    auto out = render_frame(direct, std::move(r));
    direct_models.at(id) = std::move(*out.imaging);
    return out.image;
  }

  const config::camera_settings& camera(int id) const {
    for (const auto& c : scenario.cameras)
      if (c.id == id) return c;
    throw std::out_of_range("camera");
  }

  config::scenario scenario;
  std::shared_ptr<const world::station> station;
  world::crowd crowd;
  vision::renderer direct;
  std::map<int, vision::imaging_model> direct_models;
  std::map<int, vision::imaging_model> models;
};

// Asks `router` for camera `id`'s tile of `frame` and checks it against the tile rendered here.
void expect_tile(caf::scoped_actor& self, caf::actor& router, scene& s, int id,
                 const std::shared_ptr<const world::snapshot>& frame) {
  const auto expected = s.expected(id, frame);
  self->request(router, std::chrono::seconds(60), render_atom_v, s.request(id, frame))
      .receive(
          [&](render_result& result) {
            ASSERT_TRUE(result.imaging.has_value());
            s.models.emplace(id, std::move(*result.imaging));
            ASSERT_EQ(result.image.size(), expected.size());
            EXPECT_EQ(cv::norm(result.image, expected, cv::NORM_INF), 0.0) << "camera " << id;
          },
          [&](caf::error& err) { FAIL() << "camera " << id << ": " << to_string(err); });
}

TEST(video_tile_router, each_cameras_tiles_come_from_its_worker_with_the_bytes_rendered_here) {
  scene s;
  ASSERT_GE(s.scenario.cameras.size(), 3u);
  system_config cfg(2);
  caf::actor_system system{cfg};
  auto served_a = std::make_shared<std::atomic<int>>(0);
  auto served_b = std::make_shared<std::atomic<int>>(0);
  auto none = std::make_shared<std::atomic<int>>(0);
  auto a = system.spawn(stand_in, s.scenario, s.station, served_a, none, false);
  auto b = system.spawn(stand_in, s.scenario, s.station, served_b, none, false);
  // The first camera on a, the second on b, the rest on no worker (rendered here).
  const int first = s.scenario.cameras[0].id;
  const int second = s.scenario.cameras[1].id;
  video_tile_routes routes;
  routes.hosts = {{first, a}, {second, b}};
  routes.station = s.station;
  auto router = spawn_video_tile_router(system, routes);
  {
    caf::scoped_actor self{system};
    for (int tick = 0; tick < 3; ++tick) {
      s.crowd.step();
      auto frame = s.crowd.current();
      for (const auto& w : {a, b}) self->send(w, board_atom_v, frame);
      for (const auto& c : s.scenario.cameras) expect_tile(self, router, s, c.id, frame);
    }
  }
  EXPECT_EQ(served_a->load(), 3);
  EXPECT_EQ(served_b->load(), 3);
  for (const auto& h : {router, a, b}) caf::anon_send_exit(h, caf::exit_reason::user_shutdown);
}

TEST(video_tile_router, a_lost_workers_tiles_are_rendered_here_in_flight_and_after) {
  scene s;
  system_config cfg(2);
  caf::actor_system system{cfg};
  auto served = std::make_shared<std::atomic<int>>(0);
  auto held = std::make_shared<std::atomic<int>>(0);
  // A worker that takes the tile and never answers: it is lost with the tile in flight.
  auto lost = system.spawn(stand_in, s.scenario, s.station, served, held, true);
  const int id = s.scenario.cameras[0].id;
  video_tile_routes routes;
  routes.hosts = {{id, lost}};
  routes.station = s.station;
  auto router = spawn_video_tile_router(system, routes);
  {
    caf::scoped_actor self{system};
    s.crowd.step();
    auto frame = s.crowd.current();
    self->send(lost, board_atom_v, frame);
    const auto expected = s.expected(id, frame);
    auto pending =
        self->request(router, std::chrono::seconds(60), render_atom_v, s.request(id, frame));
    for (int i = 0; i < 6000 && held->load() == 0; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_EQ(held->load(), 1) << "the worker never took the tile";
    // As a broken connection ends a remote worker's proxy.
    caf::anon_send_exit(lost, caf::exit_reason::remote_link_unreachable);
    pending.receive(
        [&](render_result& result) {
          ASSERT_TRUE(result.imaging.has_value());
          s.models.emplace(id, std::move(*result.imaging));
          EXPECT_EQ(cv::norm(result.image, expected, cv::NORM_INF), 0.0);
        },
        [&](caf::error& err) { FAIL() << to_string(err); });
    // The next tick's tile no longer goes to the lost worker.
    s.crowd.step();
    expect_tile(self, router, s, id, s.crowd.current());
  }
  EXPECT_EQ(held->load(), 1);
  EXPECT_EQ(served->load(), 0);
  caf::anon_send_exit(router, caf::exit_reason::user_shutdown);
}

// A degraded frame as a worker's render pool answers it: a smooth gradient with the imaging
// model's noise, dropout and JPEG (when `jpeg_quality` > 0).
render_result degraded_frame(unsigned jpeg_quality) {
  config::imaging_model settings;
  settings.width_px = 96;
  settings.height_px = 72;
  settings.noise_sigma = 3.0;
  settings.dropout_fraction = 0.002;
  settings.jpeg_quality = jpeg_quality;
  render_result out;
  out.imaging = vision::imaging_model(settings, 7);
  cv::Mat clean(72, 96, CV_8UC3);
  for (int y = 0; y < clean.rows; ++y)
    for (int x = 0; x < clean.cols; ++x)
      clean.at<cv::Vec3b>(y, x) = {static_cast<std::uint8_t>(x * 2),
                                   static_cast<std::uint8_t>(y * 3),
                                   static_cast<std::uint8_t>(x + y)};
  out.image = out.imaging->degrade(clean);
  return out;
}

TEST(video_tiles, a_tile_arrives_with_its_pixels_as_jpeg_bytes_or_raw_rows) {
  for (unsigned quality : {75u, 0u}) {
    auto rendered = degraded_frame(quality);
    auto tile = to_tile(rendered);
    EXPECT_EQ(tile.jpeg, quality > 0);
    const std::size_t raw = 96 * 72 * 3;
    if (quality > 0)
      EXPECT_LT(tile.bytes.size(), raw / 3) << "JPEG bytes should be far fewer than raw rows";
    else
      EXPECT_EQ(tile.bytes.size(), raw);
    // The coordinator's model went out before the frame: it comes back at the worker's state.
    vision::imaging_model before(rendered.imaging->settings(), 7);
    auto arrived = from_tile(tile, before);
    ASSERT_EQ(arrived.image.size(), rendered.image.size());
    EXPECT_EQ(cv::norm(arrived.image, rendered.image, cv::NORM_INF), 0.0) << "quality " << quality;
    ASSERT_TRUE(arrived.imaging.has_value());
    EXPECT_EQ(arrived.imaging->noise_state(), rendered.imaging->noise_state());
    EXPECT_NE(arrived.imaging->noise_state(), before.noise_state());
  }
}

TEST(video_tiles, a_tile_whose_bytes_do_not_make_it_is_refused) {
  auto short_rows = to_tile(degraded_frame(0));
  short_rows.bytes.resize(short_rows.bytes.size() / 2);
  EXPECT_THROW(from_tile(short_rows, std::nullopt), std::invalid_argument);
  auto not_jpeg = to_tile(degraded_frame(75));
  not_jpeg.bytes.assign(100, 0x55);
  EXPECT_THROW(from_tile(not_jpeg, std::nullopt), std::invalid_argument);
  auto other_size = to_tile(degraded_frame(75));
  other_size.width_px = 48;
  EXPECT_THROW(from_tile(other_size, std::nullopt), std::invalid_argument);
}

}  // namespace
}  // namespace argus::actors
