#include "actors/run_observer.hpp"

#include <utility>

namespace argus::actors {

namespace {

eval::target_choice choice_of(config::task_target by) {
  switch (by) {
    case config::task_target::pedestrian:
      return eval::target_choice::pedestrian;
    case config::task_target::pixel:
      return eval::target_choice::pixel;
    case config::task_target::first_to_enter:
      return eval::target_choice::first_to_enter;
  }
  return eval::target_choice::pedestrian;
}

}  // namespace

run_observer::run_observer(std::shared_ptr<eval::observation_log> log,
                           std::shared_ptr<live::console_state> console,
                           std::function<void(const eval::task_origin&)> also)
    : log_(std::move(log)), console_(std::move(console)), also_(std::move(also)) {}

void run_observer::traffic(int, std::uint64_t sent, std::uint64_t received) {
  if (console_) console_->add_traffic(sent, received);
}

void run_observer::picked(const task_pick& p) {
  const eval::task_origin origin{p.task, p.pedestrian, p.camera, p.tick, choice_of(p.by)};
  log_->add_origin(origin);
  if (also_) also_(origin);
}

void run_observer::turn_done(int camera, std::int64_t tick, const vision::ptz_state& pose,
                             const cv::Mat& image,
                             const std::vector<controller::look_result>& looks) {
  if (!console_) return;
  std::vector<cv::Rect2d> boxes;
  for (const auto& look : looks)
    if (look.found) boxes.push_back(look.box);
  console_->publish_camera(camera, tick, pose.pan_deg, pose.tilt_deg, pose.field_of_view_deg, image,
                           std::move(boxes));
}

}  // namespace argus::actors
