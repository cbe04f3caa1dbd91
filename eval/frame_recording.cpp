#include "eval/frame_recording.hpp"

#include "eval/truth_label.hpp"
#include "protocol/group_messages.hpp"
#include "vision/emulated_sensor.hpp"

namespace argus::eval {

controller::controller_output frame_recording::step(const controller::controller_input& in) {
  if (truth_->log)
    if (const auto frame = truth_->now()) record(in, *frame);
  auto out = inner().step(in);
  if (!truth_->log) return out;
  // Against the cancellations heard in earlier frames: within a frame, what came in before the
  // cancellation was answered before it too.
  for (const auto& m : out.messages) {
    const auto task = protocol::task_of(m.message);
    const auto kind = protocol::kind_of(m.message);
    truth_->log->add_sent(task, kind, in.tick);
    if (cancelled_.count(task) != 0 && kind != "cancel")
      truth_->log->add_sent_after_cancel(task, kind);
  }
  for (const auto& e : out.events)
    if (e.kind == events::cancel_heard::name)
      if (const auto parsed = events::parse(e.kind, e.fields_json))
        if (const auto* c = std::get_if<events::cancel_heard>(&*parsed)) cancelled_.insert(c->task);
  return out;
}

void frame_recording::record(const controller::controller_input& in,
                             const world::snapshot& snapshot) {
  const auto s = inner().status();
  const auto& camera = truth_->camera;
  const auto view = truth_->view(in.pose);
  camera_frame frame;
  frame.tick = static_cast<std::int64_t>(snapshot.tick());
  frame.camera = camera.id;
  frame.pose = in.pose;
  frame.state = static_cast<frame_state>(s.state);
  std::vector<vision::pedestrian_view> visible;
  bool looked = false;
  for (const auto& r : in.looks) {
    if (!s.task || r.task != *s.task) continue;  // a bidder's look is not the group's
    if (!looked) visible = vision::visible_pedestrians(snapshot, *truth_->station, view);
    looked = true;
    look_record rec;
    rec.task = r.task;
    rec.leader = s.role == controller::group_role::leader;
    rec.found = r.found;
    rec.score = r.score;
    if (r.found) {
      rec.box = r.box;
      const auto target = truth_->log->target_of(r.task).value_or(0);
      const auto label = label_box(r.box, target, visible, view.width_px, view.height_px);
      rec.truth = label.truth;
      rec.iou = label.iou;
      rec.observed = label.observed;
      if (sightings_ && label.truth >= 0)
        sightings_->put(frame.tick, r.task, camera.id, rec.leader, label.truth);
    }
    frame.looks.push_back(rec);
  }
  if (truth_->log->with_visible()) {
    if (!looked) visible = vision::visible_pedestrians(snapshot, *truth_->station, view);
    const cv::Rect2d image(0.0, 0.0, view.width_px, view.height_px);
    for (const auto& v : visible) {
      const auto shown = v.box & image;
      if (shown.area() <= 0.0) continue;
      frame.visible.push_back({v.id, shown, 1.0 - v.occlusion});
    }
  }
  truth_->log->add_frame(std::move(frame));
}

}  // namespace argus::eval
