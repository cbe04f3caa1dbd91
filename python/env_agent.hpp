#pragma once

#include <map>
#include <memory>

#include "controller/strategy.hpp"
#include "python/env_exchange.hpp"

namespace argus::pybridge {

/// The strategy of every camera in an argus.parallel_env run: it hands each frame's input to
/// the environment and does what the environment's action says. It keeps the signatures of
/// the tasks its camera was given (operator queries, the sensor's re-taken models) so that an
/// action names tasks, not histograms; a cancelled task is forgotten. It wants every frame, so
/// that each observation has one.
class env_agent final : public controller::strategy {
 public:
  env_agent(const controller::node_identity& me, std::shared_ptr<env_exchange> exchange);
  ~env_agent() override;

  controller::frame_plan plan(std::int64_t tick, bool looking) override;
  controller::controller_output step(const controller::controller_input& in) override;
  controller::strategy_status status() const override;

 private:
  int camera_;
  std::shared_ptr<env_exchange> exchange_;
  std::map<controller::task_id, protocol::signature> tasks_;
};

}  // namespace argus::pybridge
