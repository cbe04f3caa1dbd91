#include "actors/display_relay.hpp"

#include <utility>

#include "vision/jpeg_codec.hpp"

namespace argus::actors {

namespace {

// The console shows the frame and draws boxes on it: a little JPEG loss is not seen there, and
// a frame crosses in about a tenth of its raw size.
constexpr int display_jpeg_quality = 85;

}  // namespace

display_relay::display_relay(std::shared_ptr<node_observer> inner) : inner_(std::move(inner)) {}

void display_relay::traffic(int camera, std::uint64_t sent, std::uint64_t received) {
  inner_->traffic(camera, sent, received);
  std::lock_guard<std::mutex> guard(mutex_);
  sent_ += sent;
  received_ += received;
}

void display_relay::picked(const task_pick& pick) {
  inner_->picked(pick);
}

void display_relay::turn_done(int camera, std::int64_t tick, const vision::ptz_state& pose,
                              const cv::Mat& image,
                              const std::vector<controller::look_result>& looks) {
  inner_->turn_done(camera, tick, pose, image, looks);
  camera_display shown;
  shown.camera = camera;
  shown.tick = tick;
  shown.pose = pose;
  bool watched = false;
  {
    std::lock_guard<std::mutex> guard(mutex_);
    watched = watched_.count(camera) != 0;
  }
  // An encode per sensed frame of every camera would cost a large pixel run dearly, for frames
  // no page shows.
  if (!image.empty() && watched) {
    vision::encode_jpeg(image, display_jpeg_quality, shown.jpeg);
    for (const auto& look : looks)
      if (look.found)
        shown.boxes.insert(shown.boxes.end(),
                           {look.box.x, look.box.y, look.box.width, look.box.height});
  }
  std::lock_guard<std::mutex> guard(mutex_);
  auto& kept = latest_[camera];
  // A camera that looked at nothing in a later turn than the kept one's still shows that frame
  // (of its own tick), as in one process.
  if (shown.jpeg.empty() && !kept.jpeg.empty()) {
    kept.pose = shown.pose;
    return;
  }
  kept = std::move(shown);
}

void display_relay::watch(const std::vector<int>& cameras) {
  std::lock_guard<std::mutex> guard(mutex_);
  watched_ = std::set<int>(cameras.begin(), cameras.end());
}

live_display display_relay::take() {
  live_display out;
  std::lock_guard<std::mutex> guard(mutex_);
  out.cameras.reserve(latest_.size());
  for (auto& [camera, shown] : latest_) out.cameras.push_back(std::move(shown));
  latest_.clear();
  out.sent = std::exchange(sent_, 0);
  out.received = std::exchange(received_, 0);
  return out;
}

}  // namespace argus::actors
