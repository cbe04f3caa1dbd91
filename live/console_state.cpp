#include "live/console_state.hpp"

#include <chrono>
#include <cstdlib>
#include <opencv2/imgcodecs.hpp>
#include <type_traits>
#include <variant>

#include "fmt/format.h"

namespace argus::live {
namespace {

// How many positions a tasked target's trail keeps (one per snapshot, 15 per second).
constexpr std::size_t trail_points = 600;
// How many notable events the page's log shows.
constexpr std::size_t recent_events = 40;

double wall_now() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace

console_state::console_state(const config::scenario& scenario)
    : tick_seconds_(scenario.run.tick.count()),
      end_tick_(static_cast<std::int64_t>(scenario.run.duration / scenario.run.tick + 0.5)) {
  for (const auto& c : scenario.cameras) {
    auto& e = cameras_[c.id];
    e.x_m = c.position.x_m;
    e.y_m = c.position.y_m;
    e.pan_deg = c.pan_deg;
    e.tilt_deg = c.tilt_deg;
    e.field_of_view_deg = c.field_of_view_deg;
    e.frame.camera = c.id;
  }
}

void console_state::publish_snapshot(std::shared_ptr<const world::snapshot> frame) {
  std::lock_guard<std::mutex> guard(mutex_);
  tick_ = static_cast<std::int64_t>(frame->tick());
  for (auto& [task, t] : tasks_) {
    if (t.pedestrian < 0 || t.status != "observed") continue;
    if (const auto* who = frame->find(t.pedestrian)) {
      t.trail.push_back({who->position.x(), who->position.y()});
      if (t.trail.size() > trail_points) t.trail.pop_front();
    }
  }
  snapshot_ = std::move(frame);
}

void console_state::publish_camera(int camera, std::int64_t tick, double pan_deg, double tilt_deg,
                                   double field_of_view_deg, const cv::Mat& image,
                                   std::vector<cv::Rect2d> boxes) {
  // Shares the node's buffer: the node never writes a sensed frame again.
  put_camera(camera, tick, {pan_deg, tilt_deg, field_of_view_deg}, image, {}, std::move(boxes));
}

void console_state::publish_camera_jpeg(int camera, std::int64_t tick, double pan_deg,
                                        double tilt_deg, double field_of_view_deg,
                                        std::vector<unsigned char> jpeg,
                                        std::vector<cv::Rect2d> boxes) {
  put_camera(camera, tick, {pan_deg, tilt_deg, field_of_view_deg}, cv::Mat(), std::move(jpeg),
             std::move(boxes));
}

void console_state::put_camera(int camera, std::int64_t tick, std::array<double, 3> pose,
                               cv::Mat image, std::vector<unsigned char> jpeg,
                               std::vector<cv::Rect2d> boxes) {
  std::lock_guard<std::mutex> guard(mutex_);
  auto it = cameras_.find(camera);
  if (it == cameras_.end()) return;
  auto& e = it->second;
  e.pan_deg = pose[0];
  e.tilt_deg = pose[1];
  e.field_of_view_deg = pose[2];
  if (image.empty() && jpeg.empty()) return;  // it looked at nothing: the last frame stays
  e.frame.tick = tick;
  ++e.frame.sequence;
  e.frame.image = std::move(image);
  e.frame.jpeg = std::move(jpeg);
  e.frame.boxes = std::move(boxes);
}

void console_state::record_events(std::span<const event_line> events) {
  std::lock_guard<std::mutex> guard(mutex_);
  for (const auto& ev : events) apply(ev);
}

void console_state::note(std::string line) {
  std::lock_guard<std::mutex> guard(mutex_);
  recent_.push_back(std::move(line));
  if (recent_.size() > recent_events) recent_.pop_front();
}

namespace {

template <class E, class... Kinds>
constexpr bool is_one_of = (std::is_same_v<E, Kinds> || ...);

// The kinds the page's log lists.
struct listed {
  template <class E>
  bool operator()(const E&) const {
    return is_one_of<E, events::task_issued, events::task_cancelled, events::task_refused,
                     events::task_target, events::task_created, events::joined, events::left_task,
                     events::leader_changed, events::fault_event, events::node_recovered,
                     events::handoff, events::group_vanished, events::render_failed>;
  }
};

}  // namespace

void console_state::apply(const event_line& ev) {
  // The network's chatter is most of the log and changes nothing here: not even parsed.
  if (ev.kind == events::net_sent::name || ev.kind == events::net_received::name) return;
  auto parsed = events::parse(ev.kind, ev.fields_json);
  if (!parsed) return;
  // A camera's line that does not name its camera (written by hand) is its source's.
  std::visit(
      [&](auto& e) {
        if constexpr (requires { e.camera; })
          if (e.camera == 0 && ev.source.starts_with("camera/"))
            e.camera = std::atoi(ev.source.c_str() + std::string_view("camera/").size());
      },
      *parsed);
  if (std::visit(listed{}, *parsed)) {
    recent_.push_back(fmt::format("t={:.1f}s {} {} {}",
                                  static_cast<double>(ev.tick) * tick_seconds_, ev.source, ev.kind,
                                  ev.fields_json));
    if (recent_.size() > recent_events) recent_.pop_front();
  }
  std::visit([&](const auto& e) { take(e, ev); }, *parsed);
}

void console_state::take(const events::node_state& e, const event_line&) {
  auto cam = cameras_.find(e.camera);
  if (cam == cameras_.end()) return;
  cam->second.state = e.to;
  if (cam->second.state == "idle") cam->second.tracking.clear();
}

void console_state::take(const events::tracking& e, const event_line&) {
  if (auto cam = cameras_.find(e.camera); cam != cameras_.end()) cam->second.tracking = e.state;
}

void console_state::take(const events::task_issued& e, const event_line& ev) {
  auto& t = tasks_[static_cast<int>(e.task)];
  t.camera = e.camera;
  t.issued_tick = ev.tick;
  t.status = "issued";
  t.pedestrian = e.pedestrian.value_or(-1);
}

void console_state::take(const events::task_target& e, const event_line&) {
  auto& t = tasks_[static_cast<int>(e.task)];
  t.pedestrian = e.pedestrian;
  t.status = "observed";
}

void console_state::take(const events::task_refused& e, const event_line&) {
  tasks_[static_cast<int>(e.task)].status = "refused: " + e.reason;
}

void console_state::take(const events::task_cancelled& e, const event_line&) {
  tasks_[static_cast<int>(e.task)].status = "cancelled";
}

void console_state::take(const events::task_created& e, const event_line&) {
  groups_[static_cast<int>(e.task)] = group_entry{e.camera, {e.camera}};
}

void console_state::take(const events::joined& e, const event_line&) {
  auto& g = groups_[static_cast<int>(e.task)];
  g.members.insert(e.camera);
  g.leader = e.leader;
}

void console_state::take(const events::left_task& e, const event_line&) {
  auto g = groups_.find(static_cast<int>(e.task));
  if (g == groups_.end()) return;
  g->second.members.erase(e.camera);
  if (g->second.leader == e.camera) g->second.leader = 0;
  if (g->second.members.empty()) groups_.erase(g);
}

void console_state::take(const events::leader_changed& e, const event_line&) {
  auto& g = groups_[static_cast<int>(e.task)];
  g.members.insert(e.camera);
  g.leader = e.leader;
}

void console_state::take(const events::fault_event& e, const event_line&) {
  auto cam = cameras_.find(e.camera);
  if (!e.applied || e.fault != "crash" || cam == cameras_.end()) return;
  cam->second.alive = false;
  cam->second.state = "crashed";
  cam->second.tracking.clear();
  cam->second.frame.image = cv::Mat();
  for (auto it = groups_.begin(); it != groups_.end();) {
    it->second.members.erase(e.camera);
    it = it->second.members.empty() ? groups_.erase(it) : std::next(it);
  }
}

void console_state::take(const events::node_recovered& e, const event_line&) {
  auto cam = cameras_.find(e.camera);
  if (!e.applied || cam == cameras_.end()) return;
  cam->second.alive = true;
  cam->second.state = "idle";
}

nlohmann::json console_state::state_json() const {
  nlohmann::json out;
  std::lock_guard<std::mutex> guard(mutex_);
  const auto now = wall_now();
  const auto sent = sent_.load(std::memory_order_relaxed);
  const auto received = received_.load(std::memory_order_relaxed);
  if (samples_.empty() || now - samples_.back().wall_s >= 0.2)
    samples_.push_back({now, tick_, sent, received});
  while (samples_.size() > 2 && now - samples_.front().wall_s > 3.0) samples_.pop_front();
  const auto& first = samples_.front();
  const double span_s = now - first.wall_s;
  const auto per_s = [&](double count) { return span_s > 0.0 ? count / span_s : 0.0; };
  out["tick"] = tick_;
  out["t"] = static_cast<double>(tick_) * tick_seconds_;
  out["end_t"] = static_cast<double>(end_tick_) * tick_seconds_;
  out["finished"] = finished_.load();
  out["speed_ratio"] = per_s(static_cast<double>(tick_ - first.tick) * tick_seconds_);
  out["messages"] = {{"sent", sent},
                     {"received", received},
                     {"sent_per_s", per_s(static_cast<double>(sent - first.sent))},
                     {"received_per_s", per_s(static_cast<double>(received - first.received))},
                     {"lost_or_in_flight", sent > received ? sent - received : 0}};
  auto& pedestrians = out["pedestrians"] = nlohmann::json::array();
  if (snapshot_) {
    for (const auto& p : snapshot_->pedestrians()) {
      const auto& shirt = p.look.shirt;
      pedestrians.push_back({p.id, std::round(p.position.x() * 100.0) / 100.0,
                             std::round(p.position.y() * 100.0) / 100.0,
                             fmt::format("#{:02x}{:02x}{:02x}", shirt.r, shirt.g, shirt.b)});
    }
  }
  auto& cameras = out["cameras"] = nlohmann::json::array();
  for (const auto& [id, c] : cameras_) {
    int group = -1;
    for (const auto& [task, g] : groups_)
      if (g.members.count(id) != 0) group = task;
    cameras.push_back({{"id", id},
                       {"x", c.x_m},
                       {"y", c.y_m},
                       {"pan", c.pan_deg},
                       {"tilt", c.tilt_deg},
                       {"fov", c.field_of_view_deg},
                       {"alive", c.alive},
                       {"state", c.state},
                       {"tracking", c.tracking},
                       {"task", group},
                       {"frame", c.frame.sequence},
                       {"has_frame", !c.frame.image.empty() || !c.frame.jpeg.empty()}});
  }
  auto& groups = out["groups"] = nlohmann::json::array();
  for (const auto& [task, g] : groups_)
    groups.push_back({{"task", task},
                      {"leader", g.leader},
                      {"members", std::vector<int>(g.members.begin(), g.members.end())}});
  auto& tasks = out["tasks"] = nlohmann::json::array();
  for (const auto& [index, t] : tasks_) {
    nlohmann::json trail = nlohmann::json::array();
    // Every 5th point: the page draws a line, not each frame.
    for (std::size_t i = 0; i < t.trail.size(); i += 5) trail.push_back(t.trail[i]);
    tasks.push_back({{"task", index},
                     {"camera", t.camera},
                     {"pedestrian", t.pedestrian},
                     {"status", t.status},
                     {"issued_t", static_cast<double>(t.issued_tick) * tick_seconds_},
                     {"trail", std::move(trail)}});
  }
  out["recent"] = std::vector<std::string>(recent_.rbegin(), recent_.rend());
  return out;
}

void console_state::watch(int camera, std::chrono::steady_clock::time_point now) {
  std::lock_guard<std::mutex> guard(mutex_);
  watched_[camera] = now;
}

std::vector<int> console_state::watched(std::chrono::steady_clock::time_point now) const {
  std::vector<int> out;
  std::lock_guard<std::mutex> guard(mutex_);
  for (const auto& [camera, asked] : watched_)
    if (now - asked <= feed_watch_window) out.push_back(camera);
  return out;
}

std::optional<feed_frame> console_state::feed(int camera) const {
  feed_frame out;
  {
    std::lock_guard<std::mutex> guard(mutex_);
    const auto it = cameras_.find(camera);
    if (it == cameras_.end()) return std::nullopt;
    const auto& frame = it->second.frame;
    if (frame.image.empty() && frame.jpeg.empty()) return std::nullopt;
    out = frame;
  }
  // A worker's frame, decoded out of the lock: the run publishes while a page reads.
  if (out.image.empty()) out.image = cv::imdecode(out.jpeg, cv::IMREAD_COLOR);
  if (out.image.empty()) return std::nullopt;
  return out;
}

std::optional<camera_pose> console_state::pose(int camera) const {
  std::lock_guard<std::mutex> guard(mutex_);
  const auto it = cameras_.find(camera);
  if (it == cameras_.end()) return std::nullopt;
  const auto& c = it->second;
  return camera_pose{tick_, c.pan_deg, c.tilt_deg, c.field_of_view_deg, c.alive};
}

}  // namespace argus::live
