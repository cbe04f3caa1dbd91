#include "actors/camera_operator.hpp"

#include <algorithm>

#include "config/enum_names.hpp"
#include "config/ticks.hpp"
#include "fmt/format.h"
#include "sensing/operator_view.hpp"

namespace argus::actors {

camera_operator::camera_operator(const config::scenario& scenario, int camera_id)
    : camera_id_(camera_id) {
  for (std::size_t i = 0; i < scenario.tasks.size(); ++i) {
    const auto& t = scenario.tasks[i];
    if (t.camera != camera_id) continue;
    tasks_.push_back(
        {config::to_ticks(t.at, scenario.run.tick), static_cast<protocol::task_id>(i), t});
    if (t.cancel_at)
      cancels_.emplace_back(config::to_ticks(*t.cancel_at, scenario.run.tick),
                            static_cast<protocol::task_id>(i));
  }
  std::sort(cancels_.begin(), cancels_.end());
  std::stable_sort(tasks_.begin(), tasks_.end(),
                   [](const auto& a, const auto& b) { return a.tick < b.tick; });
}

// Merged where the scenario's own would be: a replayed run has them from its `tasks`, sorted
// the same way (by tick, then task).
void camera_operator::take_orders(const operator_board& board) {
  for (auto& order : board.take_new(board_cursor_, camera_id_)) {
    if (order.cancel) {
      const std::pair<std::int64_t, protocol::task_id> cancel{order.tick, order.task};
      cancels_.insert(std::upper_bound(cancels_.begin(), cancels_.end(), cancel), cancel);
      continue;
    }
    const auto at =
        std::upper_bound(tasks_.begin(), tasks_.end(), order.tick,
                         [](std::int64_t tick, const due_task& t) { return tick < t.tick; });
    tasks_.insert(at, due_task{order.tick, order.task, std::move(order.request)});
  }
}

std::vector<protocol::task_id> camera_operator::take_due(std::int64_t tick,
                                                         std::int64_t first_turn) {
  for (; next_task_ < tasks_.size() && tasks_[next_task_].tick <= tick; ++next_task_)
    if (tasks_[next_task_].tick >= first_turn) due_.push_back(tasks_[next_task_]);
  std::vector<protocol::task_id> cancelled;
  for (; next_cancel_ < cancels_.size() && cancels_[next_cancel_].first <= tick; ++next_cancel_) {
    const auto task = cancels_[next_cancel_].second;
    cancelled.push_back(task);
    std::erase_if(watches_, [&](const auto& w) { return w.task.task == task; });
  }
  return cancelled;
}

namespace {

// The operator's pick `request` resolved to a pedestrian and her box in `frame`, or the reason
// it is refused.
struct resolved_pick {
  int pedestrian = 0;
  std::optional<cv::Rect2d> box;
  std::string_view refusal;
};

resolved_pick resolve_pick(const config::operator_task& request, const sensing::sensed_frame* frame,
                           int entered) {
  resolved_pick out;
  if (frame == nullptr) {
    out.refusal = "no_frame";
    return out;
  }
  const auto& snap = *frame->truth;
  switch (request.by) {
    case config::task_target::pedestrian:
      out.pedestrian = request.pedestrian;
      // An id the crowd has not produced (yet) or that already left: say so, not "not in view".
      if (snap.find(out.pedestrian) == nullptr) {
        out.refusal = "no_such_pedestrian";
        return out;
      }
      break;
    case config::task_target::pixel:
      out.pedestrian = sensing::pedestrian_at(snap, *frame->station, frame->view,
                                              cv::Point2d(request.pixel.x_px, request.pixel.y_px));
      if (out.pedestrian == 0) {
        out.refusal = "no_pedestrian_at_pixel";
        return out;
      }
      break;
    case config::task_target::first_to_enter:
      out.pedestrian = entered;
      break;
  }
  out.box = sensing::operator_box(snap, *frame->station, frame->view, out.pedestrian);
  if (!out.box) out.refusal = "not_in_view";
  return out;
}

}  // namespace

void camera_operator::resolve_one(const due_task& q, const sensing::sensed_frame* frame,
                                  sensing::sensor* eye, bool with_signature, int entered,
                                  const event_sink& emit, const pick_sink& picked,
                                  std::vector<controller::operator_query>& out) const {
  auto r = resolve_pick(q.request, frame, entered);
  if (r.refusal.empty() && !eye->can_acquire(*frame)) r.refusal = "no_frame";
  if (!r.refusal.empty()) {
    emit(events::task_refused{.camera = camera_id_,
                              .task = q.task,
                              .pedestrian = r.pedestrian,
                              .reason = std::string(r.refusal)});
    return;
  }
  emit(events::task_target{.camera = camera_id_,
                           .task = q.task,
                           .pedestrian = r.pedestrian,
                           .by = std::string(config::yaml_name(q.request.by))});
  if (picked)
    picked({q.task, r.pedestrian, camera_id_, static_cast<std::int64_t>(frame->truth->tick()),
            q.request.by});
  controller::operator_query query;
  query.task.task = q.task;
  query.task.min_cameras = static_cast<std::uint16_t>(q.request.cameras_wanted);
  query.task.max_cameras = static_cast<std::uint16_t>(q.request.cameras_max());
  query.box = *r.box;
  if (with_signature) query.task.target = eye->acquire(q.task, *frame, *r.box);
  out.push_back(std::move(query));
}

std::vector<controller::operator_query> camera_operator::resolve(const sensing::sensed_frame* frame,
                                                                 sensing::sensor* eye,
                                                                 bool with_signature,
                                                                 const event_sink& emit,
                                                                 const pick_sink& picked) {
  std::vector<controller::operator_query> out;
  for (const auto& q : due_) {
    if (q.request.by == config::task_target::first_to_enter) {
      watches_.push_back({q, {}});
      if (frame)
        watches_.back().entries.prime(
            sensing::in_view(*frame->truth, *frame->station, frame->view));
      continue;
    }
    resolve_one(q, frame, eye, with_signature, 0, emit, picked, out);
  }
  due_.clear();
  if (!frame) return out;
  for (auto it = watches_.begin(); it != watches_.end();) {
    const int entered =
        it->entries.step(sensing::in_view(*frame->truth, *frame->station, frame->view));
    if (entered == 0) {
      ++it;
      continue;
    }
    resolve_one(it->task, frame, eye, with_signature, entered, emit, picked, out);
    it = watches_.erase(it);
  }
  return out;
}

}  // namespace argus::actors
