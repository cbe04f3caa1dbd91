#pragma once

#include <memory>

#include "controller/oracle_view.hpp"
#include "eval/camera_truth.hpp"
#include "eval/oracle_board.hpp"

namespace argus::eval {

/// One camera's view of the central oracle (controller/oracle_view.hpp), from the run's oracle
/// board and ground truth.
class oracle_camera_view final : public controller::oracle_view {
 public:
  oracle_camera_view(std::shared_ptr<const camera_truth> truth, std::shared_ptr<oracle_board> board)
      : truth_(std::move(truth)), board_(std::move(board)) {}

  std::optional<controller::task_id> task_of(std::int64_t tick) override;
  vision::ptz_state pose_on(controller::task_id task, bool zoom) override;
  std::optional<cv::Rect2d> target_box(controller::task_id task,
                                       const vision::ptz_state& pose) override;
  std::optional<protocol::signature> picked_signature(controller::task_id task) override {
    return board_->signature(task);
  }
  void put_picked_signature(controller::task_id task, protocol::signature signature) override {
    board_->put_signature(task, std::move(signature));
  }

 private:
  std::shared_ptr<const camera_truth> truth_;
  std::shared_ptr<oracle_board> board_;
};

}  // namespace argus::eval
