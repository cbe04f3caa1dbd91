#pragma once

#include <functional>
#include <memory>

#include "actors/node_observer.hpp"
#include "eval/observation_log.hpp"
#include "live/console_state.hpp"

namespace argus::actors {

/// What a run's host watches camera nodes for: the operator's picks, for the evaluation (into
/// `log`, and to `also`, if set: a worker passes them on to the coordinator), and the live
/// console's display (pose, frame, the sensor's boxes, traffic; `console` null for none).
class run_observer final : public node_observer {
 public:
  run_observer(std::shared_ptr<eval::observation_log> log,
               std::shared_ptr<live::console_state> console,
               std::function<void(const eval::task_origin&)> also = {});

  void traffic(int camera, std::uint64_t sent, std::uint64_t received) override;
  void picked(const task_pick& p) override;
  void turn_done(int camera, std::int64_t tick, const vision::ptz_state& pose, const cv::Mat& image,
                 const std::vector<controller::look_result>& looks) override;

 private:
  std::shared_ptr<eval::observation_log> log_;
  std::shared_ptr<live::console_state> console_;
  std::function<void(const eval::task_origin&)> also_;
};

}  // namespace argus::actors
