#pragma once

#include <map>
#include <memory>
#include <optional>

#include "controller/strategy.hpp"
#include "eval/camera_truth.hpp"
#include "eval/position_board.hpp"
#include "sensing/sensor.hpp"
#include "vision/floor_estimate.hpp"

namespace argus::eval {

/// sensing.group_geometry: calibrated (an instrument standing for calibrated cameras that share
/// where they put her on the floor, Section V): what one camera's group says of where its
/// target is, through the run's position board.
class floor_estimates {
 public:
  floor_estimates(std::shared_ptr<const camera_truth> truth, std::shared_ptr<position_board> board)
      : truth_(std::move(truth)), board_(std::move(board)) {}

  /// Where this camera, at `pose`, puts `box` on the floor.
  std::optional<vision::floor_estimate> floor_of(const vision::ptz_state& pose,
                                                 const cv::Rect2d& box, std::int64_t tick) const;
  /// The group's estimate `last` (its latest before the frame of `tick`), if still trusted.
  std::optional<vision::floor_estimate> trusted(std::optional<vision::floor_estimate> last,
                                                std::int64_t tick) const;
  /// The group's estimate of task `task`'s target before the frame of `tick`, while trusted.
  std::optional<vision::floor_estimate> group_estimate(controller::task_id task,
                                                       std::int64_t tick) const;

  const camera_truth& truth() const { return *truth_; }
  position_board& board() const { return *board_; }
  const vision::floor_rules& rules() const { return rules_; }

 private:
  std::shared_ptr<const camera_truth> truth_;
  std::shared_ptr<position_board> board_;
  vision::floor_rules rules_;
};

/// The sensor's side: a find is refused where the group's confirmed estimate says she cannot
/// be (pixels: by the found box; emulated: by the pedestrian's projected body box).
class floor_gated_sensor final : public sensing::sensor_wrapper {
 public:
  floor_gated_sensor(std::unique_ptr<sensing::sensor> inner,
                     std::shared_ptr<const floor_estimates> floor)
      : sensor_wrapper(std::move(inner)), floor_(std::move(floor)) {}

  std::vector<controller::look_result> look(const sensing::sensed_frame& frame,
                                            const std::vector<controller::look_request>& looks,
                                            const sensing::candidate_filter& admit = {}) override;

 private:
  std::shared_ptr<const floor_estimates> floor_;
};

/// The strategy's side: what a member of a task's group found goes on the board (confirmed
/// when tested against a confirmed estimate, or the task's first), and a node that looks for
/// a task's target without holding her is pointed, zoomed, at the group's latest estimate
/// where it can reach her.
class floor_sharing_strategy final : public controller::strategy_wrapper {
 public:
  floor_sharing_strategy(std::unique_ptr<controller::strategy> inner,
                         std::shared_ptr<const floor_estimates> floor)
      : strategy_wrapper(std::move(inner)), floor_(std::move(floor)) {}

  controller::controller_output step(const controller::controller_input& in) override;

 private:
  void post_estimates(const controller::controller_input& in, std::int64_t tick);

  std::shared_ptr<const floor_estimates> floor_;
};

}  // namespace argus::eval
