#include "eval/floor_sharing.hpp"

#include "eval/oracle_assignment.hpp"
#include "eval/reachability.hpp"
#include "sensing/operator_view.hpp"

namespace argus::eval {
namespace {

// Whether a find of a task's target in the frame of `tick`, whose box is `box` (none: not in
// view), can be her by the group's confirmed estimate. The estimate is read once per task and
// frame, however many candidates the sensor weighs.
class floor_gate {
 public:
  floor_gate(const floor_estimates& floor, const vision::ptz_state& pose, std::int64_t tick)
      : floor_(floor), pose_(pose), tick_(tick) {}

  bool admits(controller::task_id task, const std::optional<cv::Rect2d>& box) {
    auto it = expected_.find(task);
    if (it == expected_.end())
      it = expected_.emplace(task, floor_.group_estimate(task, tick_)).first;
    const auto& expected = it->second;
    if (!expected || !expected->confirmed) return true;
    const auto found = box ? floor_.floor_of(pose_, *box, tick_) : std::nullopt;
    return found && vision::could_be(*found, *expected,
                                     (tick_ - expected->tick) * floor_.truth().tick_length.count(),
                                     floor_.rules());
  }

 private:
  const floor_estimates& floor_;
  vision::ptz_state pose_;
  std::int64_t tick_;
  std::map<controller::task_id, std::optional<vision::floor_estimate>> expected_;
};

}  // namespace

std::optional<vision::floor_estimate> floor_estimates::floor_of(const vision::ptz_state& pose,
                                                                const cv::Rect2d& box,
                                                                std::int64_t tick) const {
  return vision::floor_estimate_of(truth_->view(pose), box, tick, rules_);
}

std::optional<vision::floor_estimate> floor_estimates::trusted(
    std::optional<vision::floor_estimate> last, std::int64_t tick) const {
  if (!last || (tick - last->tick) * truth_->tick_length.count() > rules_.trusted_s)
    return std::nullopt;
  return last;
}

std::optional<vision::floor_estimate> floor_estimates::group_estimate(controller::task_id task,
                                                                      std::int64_t tick) const {
  return trusted(board_->latest(task, tick - 1), tick);
}

std::vector<controller::look_result> floor_gated_sensor::look(
    const sensing::sensed_frame& frame, const std::vector<controller::look_request>& looks,
    const sensing::candidate_filter& admit) {
  auto gate = std::make_shared<floor_gate>(*floor_, frame.view.pose,
                                           static_cast<std::int64_t>(frame.truth->tick()));
  sensing::candidate_filter where = [gate, &frame](const sensing::candidate& c) {
    return gate->admits(c.task, c.box ? c.box
                                      : sensing::operator_box(*frame.truth, *frame.station,
                                                              frame.view, c.pedestrian));
  };
  return inner().look(frame, looks, sensing::both(admit, std::move(where)));
}

void floor_sharing_strategy::post_estimates(const controller::controller_input& in,
                                            std::int64_t tick) {
  const auto s = inner().status();
  if (!s.task || s.state != controller::node_state::performing_task) return;
  const auto last = floor_->board().latest(*s.task, tick - 1);
  const bool confirmed = vision::confirmed_by(floor_->trusted(last, tick), !last);
  for (const auto& r : in.looks) {
    if (r.task != *s.task || !r.found) continue;
    auto e = floor_->floor_of(in.pose, r.box, tick);
    if (!e) continue;
    e->confirmed = confirmed;
    floor_->board().put(*s.task, floor_->truth().camera.id,
                        s.role == controller::group_role::leader, *e);
  }
}

controller::controller_output floor_sharing_strategy::step(const controller::controller_input& in) {
  const auto frame = in.sensed ? floor_->truth().now() : nullptr;
  if (frame) post_estimates(in, static_cast<std::int64_t>(frame->tick()));
  auto out = inner().step(in);
  if (!frame) return out;
  const auto task = looked_for_unheld(inner().status(), out, found_any(in));
  if (!task) return out;
  const auto e = floor_->group_estimate(*task, static_cast<std::int64_t>(frame->tick()));
  const auto& truth = floor_->truth();
  if (!e || !reachable(truth.camera, *truth.station, e->where, floor_->rules().assumed_height_m))
    return out;
  out.command = pose_towards(truth.camera, e->where, floor_->rules().assumed_height_m);
  return out;
}

}  // namespace argus::eval
