#include "actors/camera_node.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "actors/link_outbox.hpp"
#include "actors/net_arrivals.hpp"
#include "actors/participant_ids.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "config/enum_names.hpp"
#include "config/ticks.hpp"
#include "controller/camera_controller.hpp"
#include "eval/oracle_assignment.hpp"
#include "eval/reachability.hpp"
#include "eval/truth_label.hpp"
#include "fmt/format.h"
#include "protocol/group_messages.hpp"
#include "protocol/link_model.hpp"
#include "protocol/node_network.hpp"
#include "sensing/emulated_looks.hpp"
#include "sensing/operator_view.hpp"
#include "sensing/pixel_sensor.hpp"
#include "sensing/task_targets.hpp"
#include "vision/floor_estimate.hpp"
#include "vision/imaging_model.hpp"

namespace argus::actors {
namespace {

// A message the operator or a test asks the network side to originate (the controller's own
// messages go straight to the network).
struct origination {
  int destination = protocol::broadcast;
  std::string kind;
  std::string body;
  bool expects_reply = false;
};

// An operator task for this camera (scenario `tasks:`), due at `tick`.
struct due_task {
  std::int64_t tick = 0;
  protocol::task_id task = 0;
  config::operator_task request;
};

struct camera_node_state {
  participant_info info;
  int camera_id = 0;
  bool ptz = true;
  bool up_logged = false;  // `node_up` emitted
  link_directory links;
  std::unique_ptr<protocol::node_network> network;
  net_arrivals arrivals;
  ordered_inbox<origination> to_originate;
  // What this node sends on a link is never due before the links' lookahead: it goes to the
  // link once per lookahead window (docs/network.md, "Outbox").
  link_outbox outbox{1};
  // The last turn taken: what a flush outside a turn (crash, end of run) is stamped with.
  mail_stamp last_turn{-1, static_cast<std::uint8_t>(phase::cameras), 0, 0};

  // The camera: its controller (node knowledge only), its head, its sensor.
  std::unique_ptr<controller::camera_controller> controller;
  std::optional<vision::ptz_camera> head;
  std::shared_ptr<const camera_world> world;
  vision::camera_placement placement;  // simulator knowledge: where the renderer puts it
  vision::frame_size frame;
  config::seconds tick_length{1.0 / 15.0};
  std::optional<sensing::pixel_sensor> pixels;
  std::optional<sensing::emulated_looks> emulated;
  // sensing.identity: ground_truth: finds on anyone but the task's pedestrian are refused.
  bool identity_from_truth = false;
  std::optional<vision::imaging_model> imaging;
  std::vector<controller::look_request> looks;  // asked for by the controller's last step
  std::vector<due_task> tasks;
  std::size_t next_task = 0;
  // How far this node has read the operator board (live runs).
  std::size_t operator_cursor = 0;
  std::int64_t first_turn = -1;
  // Operator cancellations for tasks issued through this camera: (tick, task), by tick.
  std::vector<std::pair<std::int64_t, protocol::task_id>> cancels;
  std::size_t next_cancel = 0;
  // first_to_enter tasks waiting for someone to enter the view.
  struct watch {
    due_task task;
    sensing::entry_watch entries;
  };
  std::vector<watch> watches;
  // The evaluation's record of this node's frames (simulator side; null = not evaluated).
  std::shared_ptr<eval::observation_log> log;
  std::shared_ptr<const world::snapshot> eval_snap;
  // The oracle strategy: the task the central oracle gives this camera, and the target's
  // signature once the camera has seen her.
  config::camera_settings settings;
  std::optional<std::uint32_t> oracle_task;
  std::map<std::uint32_t, protocol::signature> oracle_signatures;
  // controller.oracle_signature and oracle_zoom (instruments on the oracle's lead).
  bool oracle_operator_signature = false;
  bool oracle_zoom = true;
  // sensing.group_geometry and sensing.reappearance: ground_truth (instruments).
  bool geometry_hints = false;
  bool reappearance_hints = false;
  // sensing.group_geometry: calibrated: the rules of the group's floor estimates.
  vision::floor_rules floor;

  // The turn in progress (it may wait for a rendered frame).
  std::optional<tick_context> ctx;
  caf::actor clock;
  controller::controller_input input;
  std::vector<due_task> queries;
  // The world as this turn senses it (read once per turn from the board).
  std::shared_ptr<const world::snapshot> snap;
  bool idle_behaviour = true;

  caf::behavior idle;
  caf::behavior computing_relevance;
  caf::behavior performing_task;
};

using node_actor = caf::stateful_actor<camera_node_state>;

// In a turn (`ctx` given) the hand-overs the links owe for it are announced to the clock;
// outside one (a crash, the end of the run) nobody waits for them.
void hand_to_links(node_actor* self, tick_context* ctx) {
  auto& st = self->state;
  st.outbox.flush(self, st.camera_id, st.last_turn, ctx != nullptr,
                  [&](std::uint64_t peer) { ctx->relayed_to(peer); });
}

std::vector<int> neighbours_of(const link_directory& links) {
  std::vector<int> out;
  for (const auto& [n, l] : links) out.push_back(n);
  return out;
}

void flush_network(node_actor* self, tick_context& ctx) {
  auto& st = self->state;
  // One batch per link per turn, however many network messages it carries.
  std::map<int, std::vector<protocol::net_message>> by_link;
  std::uint64_t sent = 0;
  for (auto& out : st.network->take_outgoing()) {
    by_link[out.neighbour].push_back(std::move(out.message));
    ++sent;
  }
  if (sent > 0 && st.world && st.world->console) st.world->console->add_traffic(sent, 0);
  for (auto& [neighbour, batch] : by_link) {
    auto it = st.links.find(neighbour);
    if (it == st.links.end()) continue;
    st.outbox.add(it->second.participant, it->second.handle, participant_ids::camera(neighbour),
                  ctx.tick(), std::move(batch));
  }
  if (st.outbox.window_ends(ctx.tick())) hand_to_links(self, &ctx);
  for (const auto& change : st.network->take_changes())
    ctx.emit(change.up ? "neighbour_up" : "neighbour_lost",
             fmt::format(R"("camera":{},"neighbour":{})", st.camera_id, change.neighbour));
  for (const auto& f : st.network->take_failures())
    ctx.emit("peer_failed",
             fmt::format(R"("camera":{},"peer":{},"request":"{}")", st.camera_id, f.peer, f.kind));
}

vision::camera_view view_of(const camera_node_state& st) {
  vision::camera_view view;
  view.placement = st.placement;
  view.pose = st.head->state();
  view.width_px = st.frame.width_px;
  view.height_px = st.frame.height_px;
  return view;
}

// The operator's task `q` resolved to a pedestrian and her box in this frame, or the reason
// it is refused.
struct resolved_task {
  int pedestrian = 0;
  std::optional<cv::Rect2d> box;
  std::string_view refusal;
};

resolved_task resolve(camera_node_state& st, const due_task& q, const world::snapshot* snap,
                      int entered) {
  resolved_task out;
  if (snap == nullptr || !st.world) {
    out.refusal = "no_frame";
    return out;
  }
  const auto view = view_of(st);
  switch (q.request.by) {
    case config::task_target::pedestrian:
      out.pedestrian = q.request.pedestrian;
      // An id the crowd has not produced (yet) or that already left: say so, not "not in view".
      if (snap->find(out.pedestrian) == nullptr) {
        out.refusal = "no_such_pedestrian";
        return out;
      }
      break;
    case config::task_target::pixel:
      out.pedestrian = sensing::pedestrian_at(
          *snap, *st.world->station, view, cv::Point2d(q.request.pixel.x_px, q.request.pixel.y_px));
      if (out.pedestrian == 0) {
        out.refusal = "no_pedestrian_at_pixel";
        return out;
      }
      break;
    case config::task_target::first_to_enter:
      out.pedestrian = entered;
      break;
  }
  out.box = sensing::operator_box(*snap, *st.world->station, view, out.pedestrian);
  if (!out.box) out.refusal = "not_in_view";
  return out;
}

eval::target_choice choice_of(config::task_target by) {
  switch (by) {
    case config::task_target::pedestrian:
      return eval::target_choice::pedestrian;
    case config::task_target::pixel:
      return eval::target_choice::pixel;
    case config::task_target::first_to_enter:
      return eval::target_choice::first_to_enter;
  }
  return eval::target_choice::pedestrian;
}

// Her signature for `task` from this camera's own sensing, which starts its tracker on her: the
// pixels in `box`, or the emulated sensor's reading of pedestrian `pedestrian`.
protocol::signature own_signature(camera_node_state& st, controller::task_id task,
                                  const cv::Mat& image, const world::snapshot& snap,
                                  const cv::Rect& box, int pedestrian) {
  return st.pixels ? st.pixels->acquire(task, image, st.head->state(), box)
                   : st.emulated->acquire(task, snap, pedestrian);
}

// An operator's task for this camera: its signature from the camera's own sensing, or a
// refusal when the pedestrian is not in view.
void take_query(camera_node_state& st, const due_task& q, const world::snapshot* snap,
                const cv::Mat& image, int entered = 0) {
  auto r = resolve(st, q, snap, entered);
  if (r.refusal.empty() && st.pixels && image.empty()) r.refusal = "no_frame";
  if (!r.refusal.empty()) {
    st.ctx->emit("task_refused",
                 fmt::format(R"("camera":{},"task":{},"pedestrian":{},"reason":"{}")", st.camera_id,
                             q.task, r.pedestrian, r.refusal));
    return;
  }
  st.ctx->emit("task_target",
               fmt::format(R"("camera":{},"task":{},"pedestrian":{},"by":"{}")", st.camera_id,
                           q.task, r.pedestrian, config::yaml_name(q.request.by)));
  if (st.log)
    st.log->add_origin({q.task, r.pedestrian, st.camera_id, static_cast<std::int64_t>(snap->tick()),
                        choice_of(q.request.by)});
  // The oracle assigns cameras itself; it needs the pick only to look with it.
  if (st.world->oracle && !st.oracle_operator_signature) return;
  auto signature = own_signature(st, q.task, image, *snap, cv::Rect(*r.box), r.pedestrian);
  if (st.world->oracle) {
    st.world->oracle->put_signature(q.task, std::move(signature));
    return;
  }
  controller::operator_query query;
  query.task.task = q.task;
  query.task.min_cameras = static_cast<std::uint16_t>(q.request.cameras_wanted);
  query.task.max_cameras = static_cast<std::uint16_t>(q.request.cameras_max());
  query.box = *r.box;
  query.task.target = std::move(signature);
  st.input.queries.push_back(std::move(query));
}

void take_queries(camera_node_state& st, const world::snapshot* snap, const cv::Mat& image) {
  for (const auto& q : st.queries) {
    if (q.request.by == config::task_target::first_to_enter) {
      st.watches.push_back({q, {}});
      if (snap && st.world)
        st.watches.back().entries.prime(sensing::in_view(*snap, *st.world->station, view_of(st)));
      continue;
    }
    take_query(st, q, snap, image);
  }
  st.queries.clear();
  if (!snap || !st.world) return;
  for (auto it = st.watches.begin(); it != st.watches.end();) {
    const int entered = it->entries.step(sensing::in_view(*snap, *st.world->station, view_of(st)));
    if (entered == 0) {
      ++it;
      continue;
    }
    take_query(st, it->task, snap, image, entered);
    it = st.watches.erase(it);
  }
}

// The evaluation's record of this frame: pose, state and the task's looks labelled with whom
// they show (simulator knowledge; the controller never sees it).
void record_frame(camera_node_state& st) {
  if (!st.log || !st.eval_snap || !st.world) return;
  eval::camera_frame frame;
  frame.tick = static_cast<std::int64_t>(st.eval_snap->tick());
  frame.camera = st.camera_id;
  frame.pose = st.head->state();
  frame.state = static_cast<eval::frame_state>(st.controller->state());
  auto task = st.controller->task();
  if (st.world->oracle) {
    task = st.oracle_task;
    frame.state = task ? eval::frame_state::performing_task : eval::frame_state::idle;
  }
  std::vector<vision::pedestrian_view> visible;
  bool looked = false;
  for (const auto& r : st.input.looks) {
    if (!task || r.task != *task) continue;  // a bidder's look is not the group's
    if (!looked)
      visible = vision::visible_pedestrians(*st.eval_snap, *st.world->station, view_of(st));
    looked = true;
    eval::look_record rec;
    rec.task = r.task;
    rec.leader = st.world->oracle ? false : st.controller->role() == controller::group_role::leader;
    rec.found = r.found;
    rec.score = r.score;
    if (r.found) {
      rec.box = r.box;
      const auto target = st.log->target_of(r.task).value_or(0);
      const auto label =
          eval::label_box(r.box, target, visible, st.frame.width_px, st.frame.height_px);
      rec.truth = label.truth;
      rec.iou = label.iou;
      rec.observed = label.observed;
      if (st.world->sightings && label.truth >= 0)
        st.world->sightings->put(frame.tick, r.task, st.camera_id, rec.leader, label.truth);
    }
    frame.looks.push_back(rec);
  }
  if (st.log->with_visible()) {
    if (!looked)
      visible = vision::visible_pedestrians(*st.eval_snap, *st.world->station, view_of(st));
    const cv::Rect2d image(0.0, 0.0, st.frame.width_px, st.frame.height_px);
    for (const auto& v : visible) {
      const auto shown = v.box & image;
      if (shown.area() <= 0.0) continue;
      frame.visible.push_back({v.id, shown, 1.0 - v.occlusion});
    }
  }
  st.log->add_frame(std::move(frame));
}

// The oracle strategy: the central oracle's order for this frame. The camera points where the
// truth says she is and tracks her with its own sensor, from a signature taken from its own
// view the first time it sees her.
void take_oracle_order(camera_node_state& st, const world::snapshot& frame) {
  auto task = st.world->oracle->task_of(st.camera_id, frame);
  if (task == st.oracle_task) return;
  if (st.oracle_task)
    st.ctx->emit("left_task",
                 fmt::format(R"("camera":{},"task":{},"reason":"oracle","role":"member")",
                             st.camera_id, *st.oracle_task));
  if (task)
    st.ctx->emit("joined", fmt::format(R"("camera":{},"task":{},"leader":0,"reassign":false)",
                                       st.camera_id, *task));
  st.oracle_task = task;
}

void follow_oracle(camera_node_state& st, const world::snapshot* snap, const cv::Mat& image) {
  st.looks.clear();
  if (!st.oracle_task || snap == nullptr) {
    st.head->command(vision::ptz_state{st.settings.pan_deg, st.settings.tilt_deg,
                                       st.settings.field_of_view_deg});
    return;
  }
  const auto task = *st.oracle_task;
  const int target = st.log->target_of(task).value_or(0);
  st.head->command(eval::oracle_pose(st.settings, *snap, target, st.oracle_zoom));
  auto sig = st.oracle_signatures.find(task);
  if (sig == st.oracle_signatures.end() && st.oracle_operator_signature) {
    auto picked = st.world->oracle->signature(task);
    if (!picked) return;
    sig = st.oracle_signatures.emplace(task, std::move(*picked)).first;
  }
  if (sig == st.oracle_signatures.end()) {
    const auto box = sensing::operator_box(*snap, *st.world->station, view_of(st), target);
    if (!box || (st.pixels && image.empty())) return;
    sig = st.oracle_signatures
              .emplace(task, own_signature(st, task, image, *snap, cv::Rect(*box), target))
              .first;
  }
  st.looks.push_back({task, sig->second});
}

// The operator's live orders for this node (argus serve), merged where the scenario's own
// would be: a replayed run has them from its `tasks`, sorted the same way (by tick, then task).
void take_operator_orders(camera_node_state& st) {
  for (auto& order : st.world->operators->take_new(st.operator_cursor, st.camera_id)) {
    if (order.cancel) {
      const std::pair<std::int64_t, protocol::task_id> cancel{order.tick, order.task};
      st.cancels.insert(std::upper_bound(st.cancels.begin(), st.cancels.end(), cancel), cancel);
      continue;
    }
    const auto at =
        std::upper_bound(st.tasks.begin(), st.tasks.end(), order.tick,
                         [](std::int64_t tick, const due_task& t) { return tick < t.tick; });
    st.tasks.insert(at, due_task{order.tick, order.task, std::move(order.request)});
  }
}

caf::behavior& behaviour_for(camera_node_state& st) {
  switch (st.controller->state()) {
    case controller::node_state::idle:
      return st.idle;
    case controller::node_state::computing_relevance:
      return st.computing_relevance;
    case controller::node_state::performing_task:
      return st.performing_task;
  }
  return st.idle;
}

// sensing.identity: ground_truth: whether a box found for a task is on its pedestrian, by the
// evaluation's own test (eval::label_box: the box shows her and holds her visible centre). The
// visible boxes are computed on the first find asked about.
sensing::pixel_sensor::truth_check truth_box_check(camera_node_state& st,
                                                   const world::snapshot& frame) {
  if (!st.identity_from_truth || !st.log) return {};
  auto visible = std::make_shared<std::optional<std::vector<vision::pedestrian_view>>>();
  return [&st, &frame, visible](controller::task_id task, const cv::Rect& box) {
    const auto target = st.log->target_of(task);
    if (!target) return false;
    if (!*visible) *visible = vision::visible_pedestrians(frame, *st.world->station, view_of(st));
    return eval::label_box(cv::Rect2d(box), *target, **visible, st.frame.width_px,
                           st.frame.height_px)
        .observed;
  };
}

sensing::emulated_looks::truth_check truth_id_check(camera_node_state& st) {
  if (!st.identity_from_truth || !st.log) return {};
  return [&st](controller::task_id task, int id) { return st.log->target_of(task) == id; };
}

// The task whose target this node looks for without holding her: bidding with nothing found
// in this frame, or performing the task with its tracker in Wait or Search; none otherwise.
std::optional<controller::task_id> looked_for_unheld(const camera_node_state& st, bool found_now) {
  switch (st.controller->state()) {
    case controller::node_state::performing_task:
      if (st.controller->tracking() == vision::tracking_state::track) return std::nullopt;
      return st.controller->task();
    case controller::node_state::computing_relevance:
      if (found_now || st.looks.empty()) return std::nullopt;
      return st.looks.front().task;
    case controller::node_state::idle:
      break;
  }
  return std::nullopt;
}

// sensing.group_geometry and sensing.reappearance: ground_truth (instruments): a node that looks
// for a task's target without holding her, bidding with nothing found yet or with its tracker in
// Wait or Search, is pointed, zoomed, at whom its group's boxes were on in the last frame (the
// geometry), or at her true position when no camera of the group held anyone then (the
// reappearance), where it can reach him. Tracking, it follows its own tracker as the paper's
// node does.
void aim_from_group(camera_node_state& st, const world::snapshot& frame, bool found_now) {
  if (!st.world || !st.world->sightings) return;
  const auto task = looked_for_unheld(st, found_now);
  if (!task) return;
  const auto last = static_cast<std::int64_t>(frame.tick()) - 1;
  const auto who = st.world->sightings->aim(last, *task, st.camera_id, st.geometry_hints,
                                            st.reappearance_hints, st.log->target_of(*task));
  if (!who) return;
  const auto* seen = frame.find(*who);
  if (seen == nullptr ||
      !eval::reachable(st.settings, *st.world->station, seen->position, seen->look.height_m))
    return;
  st.head->command(eval::oracle_pose(st.settings, frame, *who));
}

// sensing.group_geometry: calibrated: where this node's calibrated camera puts `box` on the
// floor.
std::optional<vision::floor_estimate> floor_of(const camera_node_state& st, const cv::Rect2d& box,
                                               std::int64_t tick) {
  return vision::floor_estimate_of(view_of(st), box, tick, st.floor);
}

// The group's estimate `last` (its latest before the frame of `tick`), if still trusted.
std::optional<vision::floor_estimate> trusted(const camera_node_state& st,
                                              std::optional<vision::floor_estimate> last,
                                              std::int64_t tick) {
  if (!last || (tick - last->tick) * st.tick_length.count() > st.floor.trusted_s)
    return std::nullopt;
  return last;
}

// The group's estimate of task `task`'s target before the frame of `tick`, while trusted.
std::optional<vision::floor_estimate> group_estimate(const camera_node_state& st,
                                                     controller::task_id task, std::int64_t tick) {
  if (!st.world || !st.world->positions) return std::nullopt;
  return trusted(st, st.world->positions->latest(task, tick - 1), tick);
}

// Whether a find of task `task`'s target in the frame of `tick`, whose box is `box` (none: not
// in view), can be her by the group's confirmed estimate. The estimate is read once per task
// and frame, however many candidates the sensor weighs.
class floor_gate {
 public:
  floor_gate(const camera_node_state& st, std::int64_t tick) : st_(st), tick_(tick) {}

  bool admits(controller::task_id task, const std::optional<cv::Rect2d>& box) {
    auto it = expected_.find(task);
    if (it == expected_.end()) it = expected_.emplace(task, group_estimate(st_, task, tick_)).first;
    const auto& expected = it->second;
    if (!expected || !expected->confirmed) return true;
    const auto found = box ? floor_of(st_, *box, tick_) : std::nullopt;
    return found && vision::could_be(*found, *expected,
                                     (tick_ - expected->tick) * st_.tick_length.count(), st_.floor);
  }

 private:
  const camera_node_state& st_;
  std::int64_t tick_;
  std::map<controller::task_id, std::optional<vision::floor_estimate>> expected_;
};

// sensing.group_geometry: calibrated: a find is refused where the group's estimate says she
// cannot be (pixels: by the found box).
sensing::pixel_sensor::truth_check position_check(camera_node_state& st,
                                                  const world::snapshot& frame,
                                                  sensing::pixel_sensor::truth_check inner) {
  if (!st.world || !st.world->positions) return inner;
  auto gate = std::make_shared<floor_gate>(st, static_cast<std::int64_t>(frame.tick()));
  return [gate, inner = std::move(inner)](controller::task_id task, const cv::Rect& box) {
    return (!inner || inner(task, box)) && gate->admits(task, cv::Rect2d(box));
  };
}

// The same under emulated sensing, by the pedestrian's projected body box (the emulated
// sensor's boxes are that box, jittered).
sensing::emulated_looks::truth_check position_id_check(camera_node_state& st,
                                                       const world::snapshot& frame,
                                                       sensing::emulated_looks::truth_check inner) {
  if (!st.world || !st.world->positions) return inner;
  auto gate = std::make_shared<floor_gate>(st, static_cast<std::int64_t>(frame.tick()));
  return [&st, &frame, gate, inner = std::move(inner)](controller::task_id task, int id) {
    return (!inner || inner(task, id)) &&
           gate->admits(task, sensing::operator_box(frame, *st.world->station, view_of(st), id));
  };
}

// What this node, a member of `task`'s group, found for it goes on the board, confirmed when
// tested against a confirmed estimate (or the task's first).
void post_estimates(camera_node_state& st, const world::snapshot& frame) {
  if (!st.world || !st.world->positions) return;
  const auto task = st.controller->task();
  if (!task || st.controller->state() != controller::node_state::performing_task) return;
  const auto tick = static_cast<std::int64_t>(frame.tick());
  const auto last = st.world->positions->latest(*task, tick - 1);
  const bool confirmed = vision::confirmed_by(trusted(st, last, tick), !last);
  for (const auto& r : st.input.looks) {
    if (r.task != *task || !r.found) continue;
    auto e = floor_of(st, r.box, tick);
    if (!e) continue;
    e->confirmed = confirmed;
    st.world->positions->put(*task, st.camera_id,
                             st.controller->role() == controller::group_role::leader, *e);
  }
}

// A node that looks for a task's target without holding her is pointed, zoomed, at the group's
// latest estimate of where she is, where it can reach her.
void aim_at_estimate(camera_node_state& st, const world::snapshot& frame, bool found_now) {
  if (!st.world || !st.world->positions) return;
  const auto task = looked_for_unheld(st, found_now);
  if (!task) return;
  const auto e = group_estimate(st, *task, static_cast<std::int64_t>(frame.tick()));
  if (!e || !eval::reachable(st.settings, *st.world->station, e->where, st.floor.assumed_height_m))
    return;
  st.head->command(eval::pose_towards(st.settings, e->where, st.floor.assumed_height_m));
}

// The second half of a turn, once the frame (if any) is there: sense, decide, act.
void finish_turn(node_actor* self, const cv::Mat& image) {
  auto& st = self->state;
  auto& ctx = *st.ctx;
  const auto snap = std::move(st.snap);
  if (snap && !st.looks.empty()) {
    if (st.pixels && !image.empty()) {
      st.input.looks = st.pixels->look(image, st.head->state(), st.looks,
                                       position_check(st, *snap, truth_box_check(st, *snap)));
    } else if (st.emulated) {
      st.input.looks = st.emulated->look(*snap, *st.world->station, view_of(st), st.looks,
                                         position_id_check(st, *snap, truth_id_check(st)));
    }
  }
  take_queries(st, snap.get(), image);
  if (snap) post_estimates(st, *snap);
  record_frame(st);
  st.eval_snap.reset();
  st.input.pose = st.head->state();
  // The live console's copy of what the node saw (display only: nothing comes back).
  std::vector<cv::Rect2d> boxes;
  if (st.world && st.world->console)
    for (const auto& look : st.input.looks)
      if (look.found) boxes.push_back(look.box);
  const bool found_now = std::any_of(st.input.looks.begin(), st.input.looks.end(),
                                     [](const auto& look) { return look.found; });
  auto out = st.controller->step(st.input);
  st.input = {};
  for (auto& m : out.messages) {
    const auto kind = protocol::kind_of(m.message);
    if (st.log) st.log->add_sent(protocol::task_of(m.message), kind);
    st.network->send(m.destination, std::string(kind), protocol::encode(m.message));
  }
  for (auto& e : out.events) ctx.emit(std::move(e.kind), std::move(e.fields_json));
  if (st.world && st.world->oracle) {
    follow_oracle(st, snap.get(), image);
  } else {
    if (out.command) st.head->command(*out.command);
    st.looks = std::move(out.looks);
    if (snap) aim_from_group(st, *snap, found_now);
    if (snap) aim_at_estimate(st, *snap, found_now);
  }
  st.head->step(st.tick_length);
  if (st.world && st.world->poses) st.world->poses->put(st.camera_id, ctx.tick(), st.head->state());
  if (st.world && st.world->console) {
    const auto pose = st.head->state();
    st.world->console->publish_camera(st.camera_id, ctx.tick(), pose.pan_deg, pose.tilt_deg,
                                      pose.field_of_view_deg, image, std::move(boxes));
  }
  st.network->tick(ctx.tick());
  flush_network(self, ctx);
  self->send(st.clock, std::move(*st.ctx).finish());
  st.ctx.reset();
  self->become(behaviour_for(st));
}

void take_turn(node_actor* self, std::int64_t tick, std::uint8_t p, const caf::actor& clock) {
  auto& st = self->state;
  st.last_turn = mail_stamp{tick, p, st.info.id, 0};
  st.ctx.emplace(st.info.id, st.info.name, tick, st.info.tick_phase);
  st.clock = clock;
  auto& ctx = *st.ctx;
  if (!st.up_logged) {
    st.up_logged = true;
    st.first_turn = tick;
    ctx.emit("node_up",
             fmt::format(R"("camera":{},"type":"{}")", st.camera_id, st.ptz ? "ptz" : "static"));
  }
  std::uint64_t received = 0;
  st.arrivals.for_each_due(tick, p, [&](const mail_stamp&, int from, protocol::net_message& m) {
    st.network->receive(tick, from, m);
    ++received;
  });
  if (received > 0 && st.world && st.world->console) st.world->console->add_traffic(0, received);
  st.input.tick = tick;
  for (auto& m : st.network->take_delivered()) {
    if (auto decoded = protocol::decode(m.kind.name(), m.body)) {
      st.input.messages.push_back({m.origin, std::move(*decoded)});
      continue;
    }
    if (protocol::is_group_kind(m.kind.name())) {
      ctx.emit("bad_message", fmt::format(R"("camera":{},"origin":{},"message":"{}","bytes":{})",
                                          st.camera_id, m.origin, m.kind, m.body.size()));
      continue;
    }
    // Anything else is the operator's or a test's: logged; a liveness probe is answered.
    if (m.kind == "ping") st.network->reply(m, "pong", {});
    ctx.emit("net_received", fmt::format(R"("camera":{},"origin":{},"message":"{}","hops":{})",
                                         st.camera_id, m.origin, m.kind, m.hops));
  }
  for (auto& [stamp, o] : st.to_originate.take_due(tick, p)) {
    auto id = o.expects_reply ? st.network->request(tick, o.destination, o.kind, std::move(o.body))
                              : st.network->send(o.destination, o.kind, std::move(o.body));
    ctx.emit("net_sent", fmt::format(R"("camera":{},"destination":{},"message":"{}","id":{})",
                                     st.camera_id, o.destination, o.kind, id));
  }
  if (st.world && st.world->operators) take_operator_orders(st);
  // Tasks the operator gave while this camera was down are lost with it.
  for (; st.next_task < st.tasks.size() && st.tasks[st.next_task].tick <= tick; ++st.next_task)
    if (st.tasks[st.next_task].tick >= st.first_turn) st.queries.push_back(st.tasks[st.next_task]);
  for (; st.next_cancel < st.cancels.size() && st.cancels[st.next_cancel].first <= tick;
       ++st.next_cancel) {
    const auto task = st.cancels[st.next_cancel].second;
    st.input.cancels.push_back(task);
    std::erase_if(st.watches, [&](const auto& w) { return w.task.task == task; });
  }
  // Only a node whose state needs an image asks for one: an idle node looks at nothing (but
  // for the operator's task, or a watch for the first to enter its view).
  if (st.log && st.world) st.eval_snap = st.world->board->latest();
  if (st.world && st.world->oracle && st.eval_snap) take_oracle_order(st, *st.eval_snap);
  const bool sense = st.world && (!st.queries.empty() || !st.watches.empty() ||
                                  (!st.idle_behaviour && !st.looks.empty()) || st.oracle_task);
  st.snap = sense ? (st.eval_snap ? st.eval_snap : st.world->board->latest()) : nullptr;
  const auto& snap = st.snap;
  if (!sense || !st.pixels || !snap) {
    finish_turn(self, {});
    return;
  }
  render_request request;
  request.view = view_of(st);
  request.frame = snap;
  request.time_s = snap->time().count();
  request.field_interval_s = st.tick_length.count() / 2.0;
  request.imaging = std::move(st.imaging);
  self->request(st.world->render_pool, caf::infinite, render_atom_v, std::move(request))
      .then(
          [self](render_result& result) {
            self->state.imaging = std::move(result.imaging);
            finish_turn(self, result.image);
          },
          [self](caf::error& err) {
            auto& st = self->state;
            st.ctx->emit("render_failed", fmt::format(R"("camera":{},"error_code":{})",
                                                      st.camera_id, static_cast<int>(err.code())));
            finish_turn(self, {});
          });
}

// A turn waits until every hand-over the clock announced for it has come (docs/network.md).
void take_turn_when_ready(node_actor* self) {
  if (auto t = self->state.arrivals.take_ready()) take_turn(self, t->tick, t->phase, t->clock);
}

// Fig. 10's top level: each state is a behaviour; they share the handlers of link mail and the
// end of the run, and differ in what a tick costs (an idle node senses only for the operator).
caf::behavior state_behaviour(node_actor* self, controller::node_state state,
                              const caf::message_handler& shared) {
  const bool idle = state == controller::node_state::idle;
  return caf::message_handler{
      [self, idle](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t relayed) {
        auto& st = self->state;
        st.idle_behaviour = idle;
        st.arrivals.hold({tick, p, caf::actor_cast<caf::actor>(self->current_sender())}, relayed);
        take_turn_when_ready(self);
      },
      [state](node_state_atom) { return std::string(controller::name_of(state)); },
  }
      .or_else(shared);
}

caf::behavior camera_node(node_actor* self, const config::scenario& scenario,
                          config::camera_settings camera, link_directory links,
                          std::shared_ptr<const camera_world> world) {
  auto& st = self->state;
  st.info = camera_participant(camera);
  st.camera_id = camera.id;
  st.settings = camera;
  st.ptz = camera.type == config::camera_type::ptz;
  st.network = std::make_unique<protocol::node_network>(camera.id, neighbours_of(links), scenario);
  st.links = std::move(links);
  st.outbox = link_outbox{
      protocol::link_model::min_delay_ticks(scenario.network, scenario.run.tick.count())};
  const auto identity = controller::node_identity::from(camera);
  st.frame = identity.frame;
  st.controller = std::make_unique<controller::camera_controller>(identity, scenario);
  st.head.emplace(vision::ptz_camera::from(camera));
  st.placement = vision::camera_placement::from(camera);
  st.tick_length = scenario.run.tick;
  st.world = std::move(world);
  if (st.world) st.log = st.world->log;
  if (st.world) {
    st.identity_from_truth = scenario.sensing.identity == config::identity_source::ground_truth;
    st.oracle_operator_signature =
        scenario.controller.oracle_signature_from == config::oracle_signature::operator_pick;
    st.oracle_zoom = scenario.controller.oracle_zoom;
    st.geometry_hints = scenario.sensing.geometry == config::group_geometry::ground_truth;
    st.reappearance_hints =
        scenario.sensing.reappearance == config::reappearance_model::ground_truth;
    if (scenario.sensing.mode == config::sensing_mode::pixels) {
      st.pixels.emplace(sensing::pixel_sensor::settings_for(scenario.sensing));
      st.imaging = vision::imaging_model::for_camera(camera.imaging, scenario.run.seed, camera.id);
    } else {
      st.emulated.emplace(st.world->sensor_model, scenario.run.seed, camera.id);
    }
  }
  for (std::size_t i = 0; i < scenario.tasks.size(); ++i) {
    const auto& t = scenario.tasks[i];
    if (t.camera != camera.id) continue;
    st.tasks.push_back(
        {config::to_ticks(t.at, scenario.run.tick), static_cast<protocol::task_id>(i), t});
    if (t.cancel_at)
      st.cancels.emplace_back(config::to_ticks(*t.cancel_at, scenario.run.tick),
                              static_cast<protocol::task_id>(i));
  }
  std::sort(st.cancels.begin(), st.cancels.end());
  std::stable_sort(st.tasks.begin(), st.tasks.end(),
                   [](const auto& a, const auto& b) { return a.tick < b.tick; });
  // What the node sent before it went down was on the wire already: it still reaches the
  // links, and the fault injector waits for this node's end before the links run again.
  self->set_exit_handler([self](caf::exit_msg& msg) {
    hand_to_links(self, nullptr);
    self->quit(msg.reason);
  });
  caf::message_handler shared{
      // The run is over: the links count what is still queued as in flight.
      [self](flush_atom) {
        hand_to_links(self, nullptr);
        return done_atom_v;
      },
      [self](net_deliver_mail& mail) {
        self->state.arrivals.put(mail);
        take_turn_when_ready(self);
      },
      [self](net_retract_atom, std::uint64_t link, std::int64_t from_due) {
        self->state.arrivals.retract(link, from_due);
      },
      [self](net_originate_atom, const mail_stamp& stamp, int destination, std::string& kind,
             std::string& body, bool expects_reply) {
        self->state.to_originate.put(
            stamp, origination{destination, std::move(kind), std::move(body), expects_reply});
      },
  };
  st.idle = state_behaviour(self, controller::node_state::idle, shared);
  st.computing_relevance =
      state_behaviour(self, controller::node_state::computing_relevance, shared);
  st.performing_task = state_behaviour(self, controller::node_state::performing_task, shared);
  return st.idle;
}

}  // namespace

participant_info camera_participant(const config::camera_settings& camera) {
  participant_info info{participant_ids::camera(camera.id), fmt::format("camera/{}", camera.id),
                        phase::cameras, wake_mode::every_tick};
  info.flushes_at_end = true;
  return info;
}

caf::actor spawn_camera_node(caf::actor_system& system, const config::scenario& scenario,
                             const config::camera_settings& camera, link_directory links,
                             std::shared_ptr<const camera_world> world) {
  return system.spawn(camera_node, scenario, camera, std::move(links), std::move(world));
}

}  // namespace argus::actors
