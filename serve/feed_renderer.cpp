#include "serve/feed_renderer.hpp"

#include "opencv2/imgproc.hpp"
#include "sensing/operator_view.hpp"
#include "vision/jpeg_codec.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::serve {
namespace {

// A node's frame older than this many ticks is stale: the node has stopped looking.
constexpr std::int64_t fresh_ticks = 3;

// Added to the run seed for the display's imaging models, so that their noise is their own.
constexpr std::uint64_t display_seed_offset = 0x5e7e'd15b'1a70ULL;

std::vector<unsigned char> encode(const cv::Mat& image) {
  std::vector<unsigned char> out;
  vision::encode_jpeg(image, 80, out);
  return out;
}

}  // namespace

feed_renderer::feed_renderer(const config::scenario& scenario,
                             std::shared_ptr<const world::station> where)
    : station_(std::move(where)), tick_seconds_(scenario.run.tick.count()) {
  for (const auto& c : scenario.cameras) {
    cameras_.emplace(c.id, c);
    imaging_.emplace(c.id, vision::imaging_model::for_camera(
                               c.imaging, scenario.run.seed + display_seed_offset, c.id));
  }
}

std::optional<feed_image> feed_renderer::frame(int camera, const live::console_state& console) {
  const auto settings = cameras_.find(camera);
  if (settings == cameras_.end()) return std::nullopt;
  const auto view = console.pose(camera);
  if (!view || !view->alive) return std::nullopt;
  if (auto own = console.feed(camera); own && own->tick + fresh_ticks >= view->tick) {
    cv::Mat shown = own->image.clone();  // the node's frame is shared: draw on a copy
    for (const auto& box : own->boxes)
      cv::rectangle(shown, cv::Rect(box), cv::Scalar(0, 255, 0), 2);
    return feed_image{encode(shown), own->tick, "node"};
  }
  const auto snap = console.snapshot();
  if (!snap) return std::nullopt;
  const auto camera_view = view_of(camera, *view);
  std::lock_guard<std::mutex> guard(mutex_);
  const double time_s = snap->time().count();
  if (!renderer_) renderer_.emplace(station_);
  cv::Mat image = renderer_->render(camera_view, *snap, time_s);
  image = imaging_.at(camera).apply(image);
  return feed_image{encode(image), static_cast<std::int64_t>(snap->tick()), "display"};
}

vision::camera_view feed_renderer::view_of(int camera, const live::camera_pose& pose) const {
  const auto& settings = cameras_.at(camera);
  vision::camera_view view;
  view.placement = vision::camera_placement::from(settings);
  view.pose = {pose.pan_deg, pose.tilt_deg, pose.field_of_view_deg};
  view.width_px = static_cast<int>(settings.imaging.width_px);
  view.height_px = static_cast<int>(settings.imaging.height_px);
  return view;
}

std::optional<nlohmann::json> feed_renderer::people(int camera,
                                                    const live::console_state& console) const {
  if (cameras_.count(camera) == 0) return std::nullopt;
  const auto pose = console.pose(camera);
  const auto snap = console.snapshot();
  if (!pose || !snap) return std::nullopt;
  const auto view = view_of(camera, *pose);
  auto out = nlohmann::json::array();
  for (const auto& p : snap->pedestrians())
    if (const auto box = sensing::operator_box(*snap, *station_, view, p.id, 0.5))
      out.push_back({{"id", p.id}, {"box", {box->x, box->y, box->width, box->height}}});
  return nlohmann::json{{"camera", camera}, {"tick", snap->tick()}, {"people", out}};
}

}  // namespace argus::serve
