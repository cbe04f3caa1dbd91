#include "python/env_agent.hpp"

#include <algorithm>

namespace argus::pybridge {

env_agent::env_agent(const controller::node_identity& me, std::shared_ptr<env_exchange> exchange)
    : camera_(me.id), exchange_(std::move(exchange)) {
  exchange_->joined(camera_);
}

env_agent::~env_agent() {
  exchange_->left(camera_);
}

controller::frame_plan env_agent::plan(std::int64_t, bool) {
  controller::frame_plan p;
  p.wants_frame = true;
  return p;
}

controller::controller_output env_agent::step(const controller::controller_input& in) {
  for (const auto& q : in.queries) tasks_[q.task.task] = q.task.target;
  for (const auto& a : in.acquired) tasks_[a.task] = a.signature;
  for (const auto& look : in.looks)
    if (look.model && tasks_.count(look.task) != 0) tasks_[look.task] = *look.model;
  for (auto task : in.cancels) tasks_.erase(task);
  auto action = exchange_->exchange(camera_, in);
  controller::controller_output out;
  out.command = action.command;
  out.messages = std::move(action.messages);
  for (const auto& [task, signature] : tasks_) {
    if (action.looks &&
        std::find(action.looks->begin(), action.looks->end(), task) == action.looks->end())
      continue;
    out.looks.push_back({task, signature});
  }
  return out;
}

controller::strategy_status env_agent::status() const {
  controller::strategy_status s;
  if (tasks_.empty()) return s;
  s.state = controller::node_state::performing_task;
  s.task = tasks_.begin()->first;
  return s;
}

}  // namespace argus::pybridge
