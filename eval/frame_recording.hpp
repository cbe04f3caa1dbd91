#pragma once

#include <memory>
#include <set>

#include "controller/strategy.hpp"
#include "eval/camera_truth.hpp"
#include "eval/sighting_board.hpp"

namespace argus::eval {

/// The evaluation's record of one camera's frames (observation_log): each frame's pose and
/// state, and the looks of the task it performs labelled with whom they show (simulator
/// knowledge; the strategy never sees it); and the messages it sends, by task and kind. With a
/// sighting board (sensing.group_geometry, sensing.reappearance: ground_truth), whom each box
/// was on goes there too.
class frame_recording final : public controller::strategy_wrapper {
 public:
  frame_recording(std::unique_ptr<controller::strategy> inner,
                  std::shared_ptr<const camera_truth> truth,
                  std::shared_ptr<sighting_board> sightings = nullptr)
      : strategy_wrapper(std::move(inner)),
        truth_(std::move(truth)),
        sightings_(std::move(sightings)) {}

  controller::controller_output step(const controller::controller_input& in) override;

 private:
  void record(const controller::controller_input& in, const world::snapshot& frame);

  std::shared_ptr<const camera_truth> truth_;
  std::shared_ptr<sighting_board> sightings_;
  // Tasks whose cancellation this node has heard (its cancel_heard events).
  std::set<std::uint32_t> cancelled_;
};

}  // namespace argus::eval
