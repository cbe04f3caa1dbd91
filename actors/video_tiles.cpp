#include "actors/video_tiles.hpp"

#include <cstring>
#include <stdexcept>
#include <utility>

#include "fmt/format.h"
#include "vision/imaging_model.hpp"
#include "vision/jpeg_codec.hpp"

namespace argus::actors {

video_tile_request to_tile_request(const render_request& request) {
  video_tile_request out;
  out.camera = request.camera;
  out.pose = request.view.pose;
  out.time_s = request.time_s;
  out.field_interval_s = request.field_interval_s;
  out.imaging = request.imaging.has_value();
  if (request.imaging) out.noise_state = request.imaging->noise_state();
  return out;
}

render_request from_tile_request(const video_tile_request& tile,
                                 const config::camera_settings& camera,
                                 const video_tile_settings& settings,
                                 std::shared_ptr<const world::snapshot> frame,
                                 std::optional<vision::imaging_model> imaging) {
  if (!frame || frame->time().count() != tile.time_s)
    throw std::invalid_argument(fmt::format(
        "camera {}'s video tile is of t = {} s, and the board holds {}", tile.camera, tile.time_s,
        frame ? fmt::format("t = {} s", frame->time().count()) : std::string("no snapshot")));
  render_request out;
  out.camera = tile.camera;
  out.view = {vision::camera_placement::from(camera), tile.pose, settings.width_px,
              settings.height_px};
  out.frame = std::move(frame);
  out.time_s = tile.time_s;
  out.field_interval_s = tile.field_interval_s;
  if (tile.imaging) {
    if (!imaging) throw std::invalid_argument("a degraded video tile needs the camera's model");
    imaging->set_noise_state(tile.noise_state);
    out.imaging = std::move(imaging);
  }
  return out;
}

vision::imaging_model video_imaging_model(const config::camera_settings& camera,
                                          const video_tile_settings& settings,
                                          std::uint64_t run_seed) {
  config::imaging_model imaging = camera.imaging;
  imaging.width_px = static_cast<unsigned>(settings.width_px);
  imaging.height_px = static_cast<unsigned>(settings.height_px);
  return vision::imaging_model::for_camera(imaging, run_seed, camera.id);
}

video_tile to_tile(const render_result& result) {
  if (result.image.type() != CV_8UC3)
    throw std::invalid_argument("a video tile must be a BGR image of 8 bits a channel");
  video_tile out;
  out.width_px = result.image.cols;
  out.height_px = result.image.rows;
  if (result.imaging) out.noise_state = result.imaging->noise_state();
  if (result.imaging && !result.imaging->last_jpeg().empty()) {
    out.jpeg = true;
    out.bytes = result.imaging->last_jpeg();
    return out;
  }
  const auto row_bytes = static_cast<std::size_t>(result.image.cols) * 3;
  out.bytes.resize(row_bytes * static_cast<std::size_t>(result.image.rows));
  for (int y = 0; y < result.image.rows; ++y)
    std::memcpy(out.bytes.data() + row_bytes * static_cast<std::size_t>(y), result.image.ptr(y),
                row_bytes);
  return out;
}

render_result from_tile(video_tile tile, std::optional<vision::imaging_model> imaging) {
  render_result out;
  if (tile.jpeg) {
    try {
      out.image = vision::decode_jpeg(tile.bytes);
    } catch (const std::runtime_error& e) {
      throw std::invalid_argument(
          fmt::format("a video tile of {}x{} pixels came with {} bytes that "
                      "are not a JPEG: {}",
                      tile.width_px, tile.height_px, tile.bytes.size(), e.what()));
    }
    if (out.image.cols != tile.width_px || out.image.rows != tile.height_px)
      throw std::invalid_argument(fmt::format(
          "a video tile of {}x{} pixels came with {} bytes of JPEG that decode to {}x{}",
          tile.width_px, tile.height_px, tile.bytes.size(), out.image.cols, out.image.rows));
  } else {
    const auto expected =
        static_cast<std::size_t>(tile.width_px) * static_cast<std::size_t>(tile.height_px) * 3;
    if (tile.width_px <= 0 || tile.height_px <= 0 || tile.bytes.size() != expected)
      throw std::invalid_argument(fmt::format("a video tile of {}x{} pixels came with {} bytes",
                                              tile.width_px, tile.height_px, tile.bytes.size()));
    out.image = cv::Mat(tile.height_px, tile.width_px, CV_8UC3);
    std::memcpy(out.image.data, tile.bytes.data(), expected);
  }
  if (imaging) {
    imaging->set_noise_state(tile.noise_state);
    out.imaging = std::move(imaging);
  }
  return out;
}

}  // namespace argus::actors
