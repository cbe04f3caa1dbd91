// apply_color_response transforms each distinct colour of a frame once and paints it back;
// apply_color_response_to_every_pixel is OpenCV's passes over the whole frame. On the frames
// a run sees they must be the same bytes, or every pixel run's log would change with it.

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "config/scenario_loader.hpp"
#include "vision/capture.hpp"
#include "vision/imaging_model.hpp"
#include "vision/renderer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::vision {
namespace {

// Every camera of penn_station.yaml with its own colour response, on rendered frames (woven
// fields, as its cameras interlace) of a walking crowd at three moments.
TEST(color_response, a_rendered_frame_comes_out_as_from_every_pixel) {
  const auto scenario = config::load_scenario(ARGUS_SOURCE_DIR "/scenarios/penn_station.yaml");
  auto station = world::station::load(world::layout_path(scenario));
  world::crowd crowd(station, world::crowd_settings::from(scenario));
  renderer render(station);
  int frames = 0;
  for (int moment = 0; moment < 3; ++moment) {
    for (int k = 0; k < 100; ++k) crowd.step();
    const auto& frame = *crowd.current();
    const double t = frame.time().count();
    for (const auto& camera : scenario.cameras) {
      ASSERT_TRUE(camera.imaging.color_response_enabled) << "camera " << camera.id;
      const camera_view view{camera_placement::from(camera), ptz_camera::from(camera).state(),
                             static_cast<int>(camera.imaging.width_px),
                             static_cast<int>(camera.imaging.height_px)};
      const cv::Mat rendered = render.render_interlaced(view, frame, t, t + 1.0 / 30.0);
      cv::Mat by_colour = rendered.clone();
      cv::Mat by_pixel = rendered.clone();
      apply_color_response(by_colour, camera.imaging.response);
      apply_color_response_to_every_pixel(by_pixel, camera.imaging.response);
      EXPECT_EQ(cv::norm(by_colour, by_pixel, cv::NORM_INF), 0.0)
          << "camera " << camera.id << " at " << t << " s";
      EXPECT_GT(cv::norm(by_colour, rendered, cv::NORM_L1), 0.0) << "camera " << camera.id;
      ++frames;
    }
  }
  EXPECT_EQ(frames, 3 * static_cast<int>(scenario.cameras.size()));
}

// A frame of many colours (noise first) takes the whole-frame path: the same bytes too.
TEST(color_response, a_frame_of_many_colours_comes_out_as_from_every_pixel) {
  cv::Mat noisy(240, 320, CV_8UC3);
  cv::RNG rng(7);
  rng.fill(noisy, cv::RNG::UNIFORM, 0, 256);
  config::color_response r;
  r.hue_offset_deg = -3.8;
  r.saturation_gain = 0.97;
  r.value_gain = 0.92;
  r.tint = 0.05;
  r.tone = 0.04;
  r.shade = 0.04;
  cv::Mat by_colour = noisy.clone();
  cv::Mat by_pixel = noisy.clone();
  apply_color_response(by_colour, r);
  apply_color_response_to_every_pixel(by_pixel, r);
  EXPECT_EQ(cv::norm(by_colour, by_pixel, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace argus::vision
