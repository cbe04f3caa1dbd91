// A complete camera strategy built as a plug-in: the camera the operator tasks follows her
// alone, centring her in its frame as its sensor finds her, and gives up after `give_up_s`
// without a find. No messages: the simplest baseline beside the paper's groups.
//
//   cmake -S examples/strategies -B build-plugin -DCMAKE_PREFIX_PATH=/where/argus/is/installed
//   cmake --build build-plugin
//   argus run scenarios/penn_station_emulated.yaml \
//     --set controller.strategy=plugin:build-plugin/lone_tracker.so

#include <memory>
#include <optional>
#include <string>

#include "controller/strategy_plugin.hpp"
#include "vision/fixate_zoom.hpp"

namespace {

using namespace argus::controller;

class lone_tracker final : public strategy {
 public:
  lone_tracker(node_identity me, double tick_s) : me_(std::move(me)), tick_s_(tick_s) {}

  controller_output step(const controller_input& in) override {
    controller_output out;
    for (auto cancelled : in.cancels)
      if (task_ && task_->task == cancelled) leave("cancelled", out);
    for (const auto& q : in.queries)
      if (!task_) {
        task_ = q.task;
        last_found_ = in.tick;
        out.events.push_back({"lone_tracker_started", field("task", q.task.task)});
      }
    for (const auto& look : in.looks) {
      if (!task_ || look.task != task_->task) continue;
      if (look.model) task_->target = *look.model;  // her colours at this camera's zoom
      if (look.found) {
        last_found_ = in.tick;
        out.command = argus::vision::centring_pose(in.pose, look.box, me_.frame, 0.4);
      }
    }
    if (task_ && (in.tick - last_found_) * tick_s_ > give_up_s) leave("lost", out);
    if (task_) out.looks.push_back({task_->task, task_->target});
    return out;
  }

  strategy_status status() const override {
    strategy_status s;
    s.state = task_ ? node_state::performing_task : node_state::idle;
    if (task_) s.task = task_->task;
    return s;
  }

 private:
  static constexpr double give_up_s = 10.0;

  static std::string field(const char* name, long long value) {
    return "\"" + std::string(name) + "\":" + std::to_string(value);
  }

  void leave(const char* why, controller_output& out) {
    out.events.push_back(
        {"lone_tracker_left", field("task", task_->task) + ",\"reason\":\"" + why + "\""});
    task_.reset();
    out.command = me_.home;
  }

  node_identity me_;
  double tick_s_;
  std::optional<argus::protocol::task_description> task_;
  std::int64_t last_found_ = 0;
};

}  // namespace

ARGUS_STRATEGY_PLUGIN(registrar) {
  registrar.add({"lone_tracker",
                 [](const strategy_context& c) -> std::unique_ptr<strategy> {
                   return std::make_unique<lone_tracker>(c.me, c.scenario.run.tick.count());
                 },
                 false, "the tasked camera follows her alone, centring her (an example plug-in)"});
}
