#include "controller/oracle_strategy.hpp"

#include "fmt/format.h"

namespace argus::controller {

oracle_strategy::oracle_strategy(node_identity me, const config::scenario& scenario,
                                 std::unique_ptr<oracle_view> view)
    : me_(std::move(me)),
      view_(std::move(view)),
      operator_signature_(scenario.controller.oracle_signature_from ==
                          config::oracle_signature::operator_pick),
      zoom_(scenario.controller.oracle_zoom) {
  // nop
}

frame_plan oracle_strategy::plan(std::int64_t tick, bool) {
  frame_plan p;
  auto task = view_->task_of(tick);
  if (task != task_) {
    if (task_)
      p.events.push_back(logged(events::left_task{
          .camera = me_.id, .task = *task_, .reason = "oracle", .role = "member"}));
    if (task)
      p.events.push_back(
          logged(events::joined{.camera = me_.id, .task = *task, .leader = 0, .reassign = false}));
    task_ = task;
  }
  p.wants_frame = task_.has_value();
  return p;
}

controller_output oracle_strategy::step(const controller_input& in) {
  controller_output out;
  if (operator_signature_)
    for (const auto& q : in.queries) view_->put_picked_signature(q.task.task, q.task.target);
  for (const auto& a : in.acquired) signatures_.insert_or_assign(a.task, a.signature);
  if (!task_ || !in.sensed) {
    out.command = me_.home;
    return out;
  }
  const auto task = *task_;
  out.command = view_->pose_on(task, zoom_);
  auto sig = signatures_.find(task);
  if (sig == signatures_.end() && operator_signature_) {
    auto picked = view_->picked_signature(task);
    if (!picked) return out;
    sig = signatures_.emplace(task, std::move(*picked)).first;
  }
  if (sig == signatures_.end()) {
    if (auto box = view_->target_box(task, in.pose)) out.acquire.push_back({task, *box});
    return out;
  }
  out.looks.push_back({task, sig->second});
  return out;
}

strategy_status oracle_strategy::status() const {
  strategy_status s;
  s.state = task_ ? node_state::performing_task : node_state::idle;
  s.task = task_;
  return s;
}

}  // namespace argus::controller
