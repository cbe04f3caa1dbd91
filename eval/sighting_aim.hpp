#pragma once

#include <memory>

#include "controller/strategy.hpp"
#include "eval/camera_truth.hpp"
#include "eval/sighting_board.hpp"

namespace argus::eval {

/// sensing.group_geometry and sensing.reappearance: ground_truth (instruments): a node that
/// looks for a task's target without holding her, bidding with nothing found yet or with its
/// tracker in Wait or Search, is pointed, zoomed, at whom its group's boxes were on in the last
/// frame (the geometry: a perfectly learned map between views), or at her true position when no
/// camera of the group held anyone then (the reappearance), where it can reach him. Tracking,
/// it follows its own tracker as the paper's node does. The group's boxes come from the frame
/// recorder (frame_recording), which labels them.
class sighting_aim final : public controller::strategy_wrapper {
 public:
  sighting_aim(std::unique_ptr<controller::strategy> inner,
               std::shared_ptr<const camera_truth> truth, std::shared_ptr<sighting_board> board,
               bool geometry, bool reappearance)
      : strategy_wrapper(std::move(inner)),
        truth_(std::move(truth)),
        board_(std::move(board)),
        geometry_(geometry),
        reappearance_(reappearance) {}

  controller::controller_output step(const controller::controller_input& in) override;

 private:
  std::shared_ptr<const camera_truth> truth_;
  std::shared_ptr<sighting_board> board_;
  bool geometry_;
  bool reappearance_;
};

}  // namespace argus::eval
