#pragma once

#include <map>
#include <memory>
#include <optional>

#include "controller/oracle_view.hpp"
#include "controller/strategy.hpp"

namespace argus::controller {

/// The ground-truth oracle (controller.strategy: oracle), an upper bound: the central oracle
/// assigns cameras to tasks (eval::assign_cameras), each camera points where the truth says
/// its target is and tracks her with its own sensor, from a signature taken from its own view
/// the first time it sees her (or the operator's pick: controller.oracle_signature). No
/// messages, no groups.
class oracle_strategy final : public strategy {
 public:
  oracle_strategy(node_identity me, const config::scenario& scenario,
                  std::unique_ptr<oracle_view> view);

  /// Takes this frame's order; wants the frame whenever it has a task.
  frame_plan plan(std::int64_t tick, bool looking) override;
  controller_output step(const controller_input& in) override;
  strategy_status status() const override;
  /// Only with controller.oracle_signature: operator (it passes the pick on to the others).
  bool takes_operator_signatures() const override { return operator_signature_; }

 private:
  node_identity me_;
  std::unique_ptr<oracle_view> view_;
  bool operator_signature_ = false;
  bool zoom_ = true;
  std::optional<task_id> task_;
  std::map<task_id, protocol::signature> signatures_;
};

}  // namespace argus::controller
