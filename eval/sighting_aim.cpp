#include "eval/sighting_aim.hpp"

#include "eval/oracle_assignment.hpp"
#include "eval/reachability.hpp"

namespace argus::eval {

controller::controller_output sighting_aim::step(const controller::controller_input& in) {
  auto out = inner().step(in);
  const auto frame = in.sensed ? truth_->now() : nullptr;
  if (!frame) return out;
  const auto task = looked_for_unheld(inner().status(), out, found_any(in));
  if (!task) return out;
  const auto last = static_cast<std::int64_t>(frame->tick()) - 1;
  const auto who = board_->aim(last, *task, truth_->camera.id, geometry_, reappearance_,
                               truth_->target_of(*task));
  if (!who) return out;
  const auto* seen = frame->find(*who);
  if (seen == nullptr ||
      !reachable(truth_->camera, *truth_->station, seen->position, seen->look.height_m))
    return out;
  out.command = oracle_pose(truth_->camera, *frame, *who);
  return out;
}

}  // namespace argus::eval
