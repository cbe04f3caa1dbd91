#include "eval/oracle_camera_view.hpp"

#include "eval/oracle_assignment.hpp"
#include "sensing/operator_view.hpp"

namespace argus::eval {

std::optional<controller::task_id> oracle_camera_view::task_of(std::int64_t) {
  const auto frame = truth_->now();
  if (!frame) return std::nullopt;
  return board_->task_of(truth_->camera.id, *frame);
}

vision::ptz_state oracle_camera_view::pose_on(controller::task_id task, bool zoom) {
  return oracle_pose(truth_->camera, *truth_->now(), truth_->target_of(task).value_or(0), zoom);
}

std::optional<cv::Rect2d> oracle_camera_view::target_box(controller::task_id task,
                                                         const vision::ptz_state& pose) {
  return sensing::operator_box(*truth_->now(), *truth_->station, truth_->view(pose),
                               truth_->target_of(task).value_or(0));
}

}  // namespace argus::eval
