#pragma once

#include "eval/camera_truth.hpp"
#include "sensing/sensor.hpp"

namespace argus::eval {

/// sensing.identity: ground_truth (an instrument): finds on anyone but the task's pedestrian are
/// refused, by the evaluation's own test (label_box: the box shows her and holds her visible
/// centre; under emulated sensing, the pedestrian the candidate stands for). What tracking
/// would reach with perfect re-identification.
class truth_identity final : public sensing::sensor_wrapper {
 public:
  truth_identity(std::unique_ptr<sensing::sensor> inner, std::shared_ptr<const camera_truth> truth)
      : sensor_wrapper(std::move(inner)), truth_(std::move(truth)) {}

  std::vector<controller::look_result> look(const sensing::sensed_frame& frame,
                                            const std::vector<controller::look_request>& looks,
                                            const sensing::candidate_filter& admit = {}) override;

 private:
  std::shared_ptr<const camera_truth> truth_;
};

}  // namespace argus::eval
